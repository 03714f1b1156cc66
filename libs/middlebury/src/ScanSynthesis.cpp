#include <lvfusion/middlebury/ScanSynthesis.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lvf::middlebury
{
namespace
{
/** Per ray, the smallest horizontal range of the points `keep` accepts. */
template <typename Keep>
std::vector<float> nearestPerRay(
	const std::vector<Eigen::Vector3d>& points, const ScanBearings& bearings, Keep&& keep)
{
	std::vector<float> nearest(bearings.rays, std::numeric_limits<float>::infinity());
	for (const auto& p : points)
	{
		if (!keep(p)) continue;
		const long ray = bearings.rayOf(std::atan2(p.y(), p.x()));
		if (ray < 0) continue;
		auto& r = nearest[static_cast<size_t>(ray)];
		r = std::min(r, static_cast<float>(std::hypot(p.x(), p.y())));
	}
	return nearest;
}
}  // namespace

long ScanBearings::rayOf(double b) const
{
	const long i = std::lround(lvf::rayIndexOf(aperture, rays, b));
	return i >= 0 && i < static_cast<long>(rays) ? i : -1;
}

ScanBearings ScanBearings::fromAperture(double aperture, double resolution)
{
	return {aperture, static_cast<size_t>(std::lround(aperture / resolution)) + 1};
}

ScanBearings cameraFieldOfView(
	const MiddleburyCalib& calib, const VirtualRobotFrame& frame, double resolution)
{
	// With the camera tilted, a border column's bearing changes along it:
	// take its top, centre and bottom pixel.
	double half = 0;
	for (const double u : {0.0, double(calib.width - 1)})
		for (const double v : {0.0, calib.cy, double(calib.height - 1)})
		{
			const Eigen::Vector3d ray((u - calib.cx0) / calib.f, (v - calib.cy) / calib.f, 1);
			const Eigen::Vector3d dir = frame.directionToRobot(ray);
			half = std::max(half, std::abs(std::atan2(dir.y(), dir.x())));
		}
	// An even number of steps puts a ray on x and every ray on a multiple of
	// the resolution, as lvf-simulate's bearings are.
	const size_t steps = 2 * static_cast<size_t>(std::ceil(half / resolution - 1e-9));
	return {static_cast<double>(steps) * resolution, steps + 1};
}

mrpt::obs::CObservation2DRangeScan::Ptr synthesiseLaser(
	const std::vector<Eigen::Vector3d>& robotPoints, const ScanBearings& bearings,
	const LaserSlice& slice, mrpt::Clock::time_point stamp)
{
	const auto ranges = nearestPerRay(robotPoints, bearings, [&](const Eigen::Vector3d& p) {
		return std::abs(p.z() - slice.height) <= slice.halfWidth &&
			std::hypot(p.x(), p.y()) <= slice.maxRange;
	});
	auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
	obs->sensorLabel = "LASER";
	obs->timestamp = stamp;
	obs->aperture = static_cast<float>(bearings.aperture);
	obs->rightToLeft = true;
	obs->maxRange = static_cast<float>(slice.maxRange);
	obs->beamAperture = static_cast<float>(bearings.step());
	obs->stdError = 0.01f;	// ground truth: a centimetre or better at these scenes' depths
	obs->sensorPose = mrpt::poses::CPose3D(0, 0, slice.height, 0, 0, 0);
	obs->resizeScan(bearings.rays);
	for (size_t i = 0; i < bearings.rays; i++)
	{
		const bool valid = std::isfinite(ranges[i]);
		obs->setScanRange(i, valid ? ranges[i] : obs->maxRange);
		obs->setScanRangeValidity(i, valid);
	}
	return obs;
}

std::vector<float> truthScan(
	const std::vector<Eigen::Vector3d>& robotPoints, const ScanBearings& bearings,
	const lvf::HeightBand& band)
{
	return nearestPerRay(
		robotPoints, bearings, [&](const Eigen::Vector3d& p) { return band.contains(p.z()); });
}

}  // namespace lvf::middlebury
