#include <lvfusion/common/InputError.h>
#include <lvfusion/common/WrittenFiles.h>
#include <lvfusion/common/Medians.h>
#include <lvfusion/metrics/PoseTrajectory.h>
#include <mrpt/core/format.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

namespace lvf::metrics
{
std::vector<StampedPose> readPoseFile(const std::string& path)
{
	lvf::common::requireInputFile(path, "pose file");
	std::ifstream in(path);
	std::vector<StampedPose> poses;
	std::string line;
	for (size_t n = 1; std::getline(in, line); n++)
	{
		if (line.empty() || line[0] == '#' || line[0] == '%') continue;
		std::istringstream fields(line);
		StampedPose p;
		double x, y, yaw;
		if (!(fields >> p.frame >> p.timestamp >> x >> y >> yaw))
			throw lvf::common::InputError(path, "line " + std::to_string(n), "expected: frame timestamp x y yaw");
		p.pose = mrpt::poses::CPose2D(x, y, yaw);
		poses.push_back(p);
	}
	return poses;
}

void writePoseFile(const std::string& path, const std::vector<StampedPose>& poses)
{
	lvf::common::OutputFile out(path);
	out << "# frame timestamp[s] x[m] y[m] yaw[rad]\n";
	for (const auto& p : poses)
		out << mrpt::format(
			"%zu %.6f %.5f %.5f %.6f\n", p.frame, p.timestamp, p.pose.x(), p.pose.y(), p.pose.phi());
	out.close();
}

const StampedPose* poseStampedAt(const std::vector<StampedPose>& poses, double timestamp)
{
	const auto p = std::find_if(poses.begin(), poses.end(), [&](const StampedPose& q) {
		return std::abs(q.timestamp - timestamp) < 1e-4;
	});
	return p == poses.end() ? nullptr : &*p;
}

TrajectoryError compareTrajectories(
	const std::vector<StampedPose>& estimate, const std::vector<StampedPose>& truth,
	const mrpt::poses::CPose2D& estimateInTruth)
{
	std::vector<double> position, heading;
	for (const auto& e : estimate)
	{
		const auto t = poseStampedAt(truth, e.timestamp);
		if (!t) continue;
		const auto pose = estimateInTruth + e.pose;
		position.push_back(std::hypot(pose.x() - t->pose.x(), pose.y() - t->pose.y()));
		heading.push_back(std::abs(mrpt::math::wrapToPi(pose.phi() - t->pose.phi())));
	}
	TrajectoryError err;
	err.matched = position.size();
	err.medianPosition = lvf::common::upperMedian(position, double(NAN));
	err.medianHeading = lvf::common::upperMedian(heading, double(NAN));
	err.maxPosition = position.empty() ? NAN : *std::max_element(position.begin(), position.end());
	return err;
}

}  // namespace lvf::metrics
