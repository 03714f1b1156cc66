#pragma once
// A simulated world's frames for lvf-bench, simulated once with what every
// method needs: the rectified grey pair (for the dense matchers) and the
// truth scans (for the scores). The box room's figures and the seeded rooms'
// both read them.

#include "StageMedians.h"

#include <lvfusion/depth/DenseStereoBaseline.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>

#include <string>
#include <vector>

namespace lvf::bench
{
struct SimulatedFrames
{
	/** Every pose of `world`'s path through a simulator with `sensors`,
	 * with the seen truth scans (the left depth itself is dropped). */
	explicit SimulatedFrames(
		const lvf::simulation::World& world,
		const lvf::simulation::CStereoLaserSimulator::TOptions& sensors = {});

	std::vector<lvf::simulation::CStereoLaserSimulator::Frame> frames;
	std::vector<cv::Mat1b> left, right;	 // rectified grey
	lvf::evaluation::RectifiedGeometry geometry;

	/** Fused scan of frame k by dense matching over [options' z_min, z_max]
	 * (MethodRuns.h); with `times`, its stages recorded as `name`. */
	mrpt::obs::CObservation2DRangeScan::Ptr dense(
		size_t k, lvf::depth::DenseMatcher matcher, const lvf::fusion::CLaserStereoFusion::TOptions& options,
		StageMedians* times = nullptr, const std::string& name = {}) const;

	/** DESIGN.md's figures of `fused` on frame k, over the bearings in view
	 * within options' z_max. */
	lvf::metrics::FusionScore score(
		size_t k, const mrpt::obs::CObservation2DRangeScan& fused,
		const lvf::fusion::CLaserStereoFusion::TOptions& options) const;
};

/** One line of recall / phantom rate / range error per method, after `indent`. */
void printScoreLine(std::ostream& out, const std::string& method, const lvf::metrics::FusionScore& s,
	const std::string& indent = "  ");

}  // namespace lvf::bench
