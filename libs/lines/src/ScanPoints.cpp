#include <lvfusion/lines/ScanPoints.h>

#include <cmath>

namespace lvf::lines
{
ScanPoints scanPoints(const mrpt::obs::CObservation2DRangeScan& scan)
{
	ScanPoints out;
	const auto& pose = scan.sensorPose;
	out.origin = Eigen::Vector2d(pose.x(), pose.y());
	const double c = std::cos(pose.yaw()), s = std::sin(pose.yaw());
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
		out.xy.emplace_back(
			out.origin.x() + c * lx - s * ly, out.origin.y() + s * lx + c * ly);
		out.ray.push_back(i);
	}
	return out;
}

}  // namespace lvf::lines
