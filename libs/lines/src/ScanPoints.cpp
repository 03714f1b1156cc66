#include <lvfusion/lines/ScanPoints.h>

#include <cmath>

namespace lvf::lines
{
ScanPoints scanPoints(const mrpt::obs::CObservation2DRangeScan& scan)
{
	ScanPoints out;
	const auto& pose = scan.sensorPose;
	out.origin = Eigen::Vector2d(pose.x(), pose.y());
	// The scan's plane onto the floor by the whole rotation, not the yaw
	// alone: a laser mounted upside down (rolled 180 degrees) scans its rays
	// in the opposite order, and by its yaw alone the room came out
	// mirrored. For an upright laser these are cos(yaw), -sin(yaw), ...
	const mrpt::math::CMatrixDouble33 R = pose.getRotationMatrix();
	const double r00 = R(0, 0), r01 = R(0, 1), r10 = R(1, 0), r11 = R(1, 1);
	const size_t n = scan.getScanSize();
	out.xy.reserve(n);
	out.ray.reserve(n);
	for (size_t i = 0; i < n; i++)
	{
		if (!scan.getScanRangeValidity(i)) continue;
		const double r = scan.getScanRange(i);
		if (!std::isfinite(r) || r <= 0 || r >= scan.maxRange) continue;
		const double a = scan.getScanAngle(i);
		const double lx = r * std::cos(a), ly = r * std::sin(a);
		out.xy.emplace_back(out.origin.x() + r00 * lx + r01 * ly, out.origin.y() + r10 * lx + r11 * ly);
		out.ray.push_back(i);
	}
	return out;
}

}  // namespace lvf::lines
