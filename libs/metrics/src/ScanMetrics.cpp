#include <lvfusion/metrics/ScanMetrics.h>
#include <mrpt/vision/pinhole.h>

#include <cmath>

namespace lvf::metrics
{
std::vector<bool> bearingsInView(
	const mrpt::obs::CObservation2DRangeScan& scan,
	const std::vector<float>& truth,
	const mrpt::obs::CObservationStereoImages& stereo, const HeightBand& band,
	double rangeIfNoTruth)
{
	const size_t n = scan.getScanSize();
	std::vector<bool> inView(n, false);
	const mrpt::poses::CPose3D camera(stereo.cameraPose);
	const auto& cam = stereo.leftCamera;
	for (size_t i = 0; i < n; i++)
	{
		const double range = std::isfinite(truth[i]) ? truth[i] : rangeIfNoTruth;
		const double bearing = scan.getScanAngle(i);
		double x, y, z;
		scan.sensorPose.composePoint(
			range * std::cos(bearing), range * std::sin(bearing), 0, x, y, z);
		for (double h = band.low; h <= band.high + 1e-9 && !inView[i]; h += 0.05)
		{
			const mrpt::math::TPoint3D p = camera.inverseComposePoint({x, y, h});
			if (p.z <= 0) continue;
			mrpt::img::TPixelCoordf px;
			mrpt::vision::pinhole::projectPoint_with_distortion(p, cam, px);
			inView[i] = px.x >= 0 && px.y >= 0 && px.x <= cam.ncols - 1 &&
				px.y <= cam.nrows - 1;
		}
	}
	return inView;
}

std::vector<bool> hiddenBearings(
	const mrpt::obs::CObservation2DRangeScan& laser,
	const std::vector<float>& truth, const std::vector<bool>& inView,
	double margin)
{
	std::vector<bool> hidden(truth.size(), false);
	for (size_t i = 0; i < truth.size(); i++)
	{
		const double laserRange = laser.getScanRangeValidity(i)
			? laser.getScanRange(i)
			: laser.maxRange;
		hidden[i] = inView[i] && std::isfinite(truth[i]) &&
			truth[i] < laserRange - margin;
	}
	return hidden;
}

}  // namespace lvf::metrics
