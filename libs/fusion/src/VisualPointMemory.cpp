#include <lvfusion/common/IniSection.h>
#include <lvfusion/fusion/VisualPointMemory.h>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace lvf::fusion
{
using lvf::common::writeOption;

void VisualPointMemory::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	maxTravel = ini.real("max_travel", maxTravel, 0, 1000);
	ini.rejectUnknownKeys();
}

void VisualPointMemory::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "max_travel", maxTravel, "keep visual points of earlier frames, moved by odometry, where the cameras cannot look now, until the robot has driven this far since they were seen; 0: off (needs odometry: lvf-fuse takes it from the rawlog) [m]");
}

namespace
{
/** MRPT's pose as an Eigen rigid transform (its frame -> its parent's). */
Eigen::Isometry3d rigid(const mrpt::poses::CPose3D& pose)
{
	Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
	t.linear() = pose.getRotationMatrix().asEigen();
	t.translation() << pose.x(), pose.y(), pose.z();
	return t;
}
}  // namespace

std::vector<lvf::depth::VisualPoint> VisualPointMemory::recall(
	const mrpt::poses::CPose2D& odometry, const lvf::evaluation::RectifiedGeometry& geometry,
	const SearchedView& view)
{
	// A pose that is no pose (a corrupt odometry record): nothing can be
	// moved by it, so forget, and start again from the next good one.
	if (!(std::isfinite(odometry.x()) && std::isfinite(odometry.y()) && std::isfinite(odometry.phi())))
	{
		clear();
		return {};
	}
	if (m_hasPose) m_travel += (odometry - m_pose).norm();
	m_pose = odometry, m_hasPose = true;
	// Two transforms per frame, one product per point (MRPT's per-point
	// composePoint took ~0.1 us each on a few thousand points a frame).
	const Eigen::Isometry3d robotFromOdometry = rigid(mrpt::poses::CPose3D(odometry)).inverse();
	const Eigen::Isometry3d cameraFromOdometry = rigid(geometry.leftPose).inverse() * robotFromOdometry;
	// Whether the present search could have found the point: in front of
	// the camera within the searched depths, inside the searched pixels of
	// the left image, its match inside the right one, neither on a pixel
	// no camera imaged.
	auto marked = [](const cv::Mat1b& marks, double u, double v) {
		return !marks.empty() && marks(static_cast<int>(v + 0.5), static_cast<int>(u + 0.5)) != 0;
	};
	auto inSearchedView = [&](const Eigen::Vector3d& c) {
		if (!(c.z() >= view.zMin && c.z() <= view.zMax)) return false;
		const double u = geometry.cx + geometry.f * c.x() / c.z(), v = geometry.cy + geometry.f * c.y() / c.z();
		if (!(u >= view.firstColumn && u <= view.lastColumn && v >= view.firstRow && v <= view.lastRow)) return false;
		const double uRight = u + geometry.cxOffset - geometry.fB() / c.z();
		if (!(uRight >= view.firstRightColumn && uRight <= view.lastRightColumn)) return false;
		return !marked(view.leftNotImaged, u, v) && !marked(view.rightNotImaged, uRight, v);
	};
	constexpr float kNoPixel = std::numeric_limits<float>::quiet_NaN();
	std::vector<lvf::depth::VisualPoint> out;
	size_t kept = 0;
	for (const auto& p : m_points)
	{
		if (m_travel - p.seenAtTravel > m_options.maxTravel || inSearchedView(cameraFromOdometry * p.odom))
			continue;
		m_points[kept++] = p;
		out.push_back({kNoPixel, kNoPixel, kNoPixel, kNoPixel, robotFromOdometry * p.odom});
	}
	m_points.resize(kept);
	return out;
}

void VisualPointMemory::remember(const std::vector<lvf::depth::VisualPoint>& points)
{
	if (!m_hasPose) return;
	const Eigen::Isometry3d odometryFromRobot = rigid(mrpt::poses::CPose3D(m_pose));
	m_points.reserve(m_points.size() + points.size());
	for (const auto& p : points) m_points.push_back({odometryFromRobot * p.robot, m_travel});
}

}  // namespace lvf::fusion
