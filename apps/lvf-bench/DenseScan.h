#pragma once
// The dense baselines' fused scan, as lvf-bench compares them with the
// paper's method: a whole-image disparity map (DenseStereoBaseline.h) turned
// into visual points on the fusion's pixel grid and through the same
// ScanFusion, so that every method is scored by the same rules.

#include "StageMedians.h"

#include <lvfusion/depth/DenseStereoBaseline.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>

#include <string>

namespace lvf::bench
{
/** The fused scan of `laser` with the dense matcher's points over disparities
 * from depth `zMin` out; with `times`, the time of its two stages
 * (matching, disparity -> fused scan) recorded as `name`. */
mrpt::obs::CObservation2DRangeScan::Ptr denseFusedScan(
	const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& geometry,
	const lvf::fusion::CLaserStereoFusion::TOptions& options, double zMin,
	const mrpt::obs::CObservation2DRangeScan& laser, lvf::depth::DenseMatcher matcher,
	StageMedians* times = nullptr, const std::string& name = {});

}  // namespace lvf::bench
