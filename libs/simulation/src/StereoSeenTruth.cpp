#include <lvfusion/common/LaserRange.h>
#include <lvfusion/common/OpenCvCamera.h>
#include <lvfusion/simulation/StereoSeenTruth.h>

#include <cmath>
#include <limits>

namespace lvf::simulation
{
StereoSeenTruth::StereoSeenTruth(
	const mrpt::img::TStereoCamera& calibration, const mrpt::poses::CPose3D& leftCameraOnRobot,
	const mrpt::poses::CPose3D& rightOfLeft, const HeightBand& band, int margin)
	: m_calibration(calibration),
	  m_leftCamera(leftCameraOnRobot),
	  m_rightOfLeft(rightOfLeft),
	  m_band(band),
	  m_margin(margin),
	  m_leftRays(calibration.leftCamera, 1)
{
}

namespace
{
bool inside(double u, double v, const mrpt::img::TCamera& camera, int margin)
{
	return u >= margin && v >= margin && u <= camera.ncols - 1.0 - margin && v <= camera.nrows - 1.0 - margin;
}
}  // namespace

std::vector<float> StereoSeenTruth::scan(
	const cv::Mat1f& leftDepth, const mrpt::obs::CObservation2DRangeScan& scanGeometry) const
{
	const auto& right = m_calibration.rightCamera;
	// The left pixels whose points lie in the band, in the right camera's
	// frame for one projection of them all, and in the laser's.
	std::vector<cv::Point3d> inRight;
	std::vector<mrpt::math::TPoint3D> inLaser;
	for (int v = m_margin; v < leftDepth.rows - m_margin; v++)
		for (int u = m_margin; u < leftDepth.cols - m_margin; u++)
		{
			const float z = leftDepth(v, u);
			if (!std::isfinite(z)) continue;
			const mrpt::math::TPoint3D pLeft(m_leftRays.rayX(u, v) * z, m_leftRays.rayY(u, v) * z, z);
			const auto pRobot = m_leftCamera.composePoint(pLeft);
			if (!m_band.contains(pRobot.z)) continue;
			const auto pRight = m_rightOfLeft.inverseComposePoint(pLeft);
			if (pRight.z <= 0) continue;
			inRight.emplace_back(pRight.x, pRight.y, pRight.z);
			inLaser.push_back(scanGeometry.sensorPose.inverseComposePoint(pRobot));
		}
	std::vector<float> ranges(scanGeometry.getScanSize(), std::numeric_limits<float>::infinity());
	if (inRight.empty() || ranges.size() < 2) return ranges;
	// Through the right camera's lens, every coefficient, and only what lies
	// inside its view (OpenCvCamera.h: a lens polynomial past its largest
	// radius would fold points from beside the view back into the image).
	const auto pixels = lvf::common::pixelsInView(inRight, right);
	for (size_t k = 0; k < inRight.size(); k++)
	{
		if (!pixels[k] || !inside(pixels[k]->x, pixels[k]->y, right, m_margin)) continue;
		const auto& p = inLaser[k];
		const long ray = std::lround(rayIndexOf(scanGeometry, std::atan2(p.y, p.x)));
		if (ray < 0 || ray >= static_cast<long>(ranges.size())) continue;
		ranges[static_cast<size_t>(ray)] = std::min(ranges[static_cast<size_t>(ray)], static_cast<float>(std::hypot(p.x, p.y)));
	}
	return ranges;
}

}  // namespace lvf::simulation
