#pragma once
// How lvf-bench runs each method on a frame and times it: the dense
// baselines' fused scan — a whole-image disparity map (DenseStereoBaseline.h)
// turned into visual points on the fusion's pixel grid and through the same
// ScanFusion, so that every method is scored by the same rules — and the
// fusion's own stage times, recorded alike.

#include "StageMedians.h"

#include <lvfusion/depth/DenseStereoBaseline.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>

#include <array>
#include <string>
#include <utility>

namespace lvf::bench
{
/** The methods' names in every table lvf-bench prints. */
inline const std::string kFusionName = "fusion (this paper)";
inline const std::string kSgbmName = "StereoSGBM 3-way";
inline const std::string kBmName = "StereoBM";
/** The dense baselines, in the order every table runs and prints them. */
inline const std::array<std::pair<lvf::depth::DenseMatcher, std::string>, 2> kDenseMethods{
	{{lvf::depth::DenseMatcher::SemiGlobal, kSgbmName}, {lvf::depth::DenseMatcher::Block, kBmName}}};

/** The fused scan of `laser` with the dense matcher's points over disparities
 * from depth `zMin` out; with `times`, the time of its two stages
 * (matching, disparity -> fused scan) recorded as `name`. */
mrpt::obs::CObservation2DRangeScan::Ptr denseFusedScan(
	const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& geometry,
	const lvf::fusion::CLaserStereoFusion::TOptions& options, double zMin,
	const mrpt::obs::CObservation2DRangeScan& laser, lvf::depth::DenseMatcher matcher,
	StageMedians* times = nullptr, const std::string& name = {});

/** Records one frame's stage times of the fusion as `name`. */
void recordFusionTimes(
	StageMedians& times, const std::string& name, const lvf::fusion::CLaserStereoFusion::StageTimes& t);

}  // namespace lvf::bench
