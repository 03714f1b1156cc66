#include "MethodRuns.h"

#include <chrono>

namespace lvf::bench
{
mrpt::obs::CObservation2DRangeScan::Ptr denseFusedScan(
	const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& geometry,
	const lvf::fusion::CLaserStereoFusion::TOptions& options, double zMin,
	const mrpt::obs::CObservation2DRangeScan& laser, lvf::depth::DenseMatcher matcher, StageMedians* times,
	const std::string& name)
{
	using Clock = std::chrono::steady_clock;
	auto ms = [](Clock::time_point a, Clock::time_point b) {
		return std::chrono::duration<double, std::milli>(b - a).count();
	};
	const auto t0 = Clock::now();
	const auto d = lvf::depth::denseDisparity(left, right, geometry, zMin, matcher);
	const auto t1 = Clock::now();
	const auto points = lvf::depth::disparityToPoints(
		d, geometry, options.band, zMin, options.depth.zMax, options.depth.pixelStride);
	const lvf::fusion::ScanFusion fusion(options.fusion);
	auto fused = lvf::fusion::ScanFusion::fuse(laser, fusion.visualRanges(laser, points));
	if (times)
	{
		times->add(name, "matching", ms(t0, t1));
		times->add(name, "to_scan", ms(t1, Clock::now()));
	}
	return fused;
}

void recordFusionTimes(
	StageMedians& times, const std::string& name, const lvf::fusion::CLaserStereoFusion::StageTimes& t)
{
	for (const auto& [stage, ms] : {std::pair{"lines", t.lines}, {"model", t.model}, {"rectify", t.rectify},
			 {"evaluate", t.evaluate}, {"search", t.search}, {"fuse", t.fuse}})
		times.add(name, stage, ms);
}

}  // namespace lvf::bench
