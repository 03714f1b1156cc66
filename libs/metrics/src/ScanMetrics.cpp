#include <lvfusion/common/LaserRange.h>
#include <lvfusion/common/OpenCvCamera.h>
#include <lvfusion/metrics/ScanMetrics.h>

#include <algorithm>
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
	const mrpt::poses::CPose3D camera(stereo.cameraPose);
	// Every bearing's band column, sampled every 5 cm, in the camera frame.
	std::vector<cv::Point3d> points;
	std::vector<size_t> bearingOf;
	for (size_t i = 0; i < n; i++)
	{
		const double range = std::isfinite(truth[i]) ? truth[i] : rangeIfNoTruth;
		const double bearing = scan.getScanAngle(i);
		double x, y, z;
		scan.sensorPose.composePoint(
			range * std::cos(bearing), range * std::sin(bearing), 0, x, y, z);
		for (double h = band.low; h <= band.high + 1e-9; h += 0.05)
		{
			const mrpt::math::TPoint3D p = camera.inverseComposePoint({x, y, h});
			if (p.z <= 0) continue;
			points.emplace_back(p.x, p.y, p.z);
			bearingOf.push_back(i);
		}
	}
	// Through the lens, every coefficient (lvf::common::pixelsInView; MRPT's
	// projectPoint_with_distortion, used before, reads five and folds the
	// points of a wide scan's side bearings back into the image).
	const auto pixels = lvf::common::pixelsInView(points, stereo.leftCamera);
	std::vector<bool> inView(n, false);
	for (size_t k = 0; k < points.size(); k++)
		if (pixels[k]) inView[bearingOf[k]] = true;
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
		hidden[i] = inView[i] && std::isfinite(truth[i]) &&
			truth[i] < laserRangeOrMax(laser, i) - margin;
	}
	return hidden;
}

}  // namespace lvf::metrics

namespace lvf::metrics
{
void FusionScore::add(const FusionScore& o)
{
	inView += o.inView;
	hidden += o.hidden;
	recalled += o.recalled;
	phantoms += o.phantoms;
	withTruth += o.withTruth;
	seenHidden += o.seenHidden;
	seenRecalled += o.seenRecalled;
	errors.insert(errors.end(), o.errors.begin(), o.errors.end());
	hiddenErrors.insert(hiddenErrors.end(), o.hiddenErrors.begin(), o.hiddenErrors.end());
}

std::vector<BearingVerdict> judgeBearings(
	const mrpt::obs::CObservation2DRangeScan& laser,
	const mrpt::obs::CObservation2DRangeScan& fused, const std::vector<float>& truth,
	const std::vector<bool>& inView, double maxRange)
{
	std::vector<BearingVerdict> verdicts(truth.size());
	const auto hidden = hiddenBearings(laser, truth, inView);
	for (size_t i = 0; i < truth.size(); i++)
	{
		if (!inView[i]) continue;
		const double t = truth[i];
		const double l = laserRangeOrMax(laser, i), f = laserRangeOrMax(fused, i);
		// Beyond Zmax vision is not asked to see; count the bearing only if
		// the laser or the truth puts something within it.
		if (std::min(t, l) > maxRange && f >= std::min<double>(l, maxRange)) continue;
		BearingVerdict& v = verdicts[i];
		v.scored = true;
		v.phantom = f < std::min(t, l) - 0.10;
		v.hidden = hidden[i] && t <= maxRange;
		v.recalled = v.hidden && f <= t + 0.10;
	}
	return verdicts;
}

FusionScore scoreVerdicts(
	const std::vector<BearingVerdict>& verdicts, const mrpt::obs::CObservation2DRangeScan& fused,
	const std::vector<float>& truth, double maxRange, const std::vector<float>* seenTruth)
{
	FusionScore s;
	for (size_t i = 0; i < truth.size(); i++)
	{
		const BearingVerdict& v = verdicts[i];
		if (!v.scored) continue;
		const double t = truth[i], f = laserRangeOrMax(fused, i);
		s.inView++;
		s.phantoms += v.phantom;
		if (std::isfinite(t) && t <= maxRange)
		{
			s.withTruth++;
			s.errors.push_back(static_cast<float>(std::abs(f - t)));
		}
		if (!v.hidden) continue;
		s.hidden++;
		s.recalled += v.recalled;
		if (seenTruth && seenByBothCameras((*seenTruth)[i], truth[i]))
		{
			s.seenHidden++;
			s.seenRecalled += v.recalled;
		}
		s.hiddenErrors.push_back(static_cast<float>(std::abs(f - t)));
	}
	return s;
}

FusionScore scoreFusedScan(
	const mrpt::obs::CObservation2DRangeScan& laser,
	const mrpt::obs::CObservation2DRangeScan& fused, const std::vector<float>& truth,
	const std::vector<bool>& inView, double maxRange, const std::vector<float>* seenTruth)
{
	return scoreVerdicts(judgeBearings(laser, fused, truth, inView, maxRange), fused, truth, maxRange, seenTruth);
}
}  // namespace lvf::metrics
