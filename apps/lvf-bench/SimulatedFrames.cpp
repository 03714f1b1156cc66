#include "SimulatedFrames.h"

#include "MethodRuns.h"

#include <lvfusion/evaluation/RectifiedStereo.h>

#include <iomanip>
#include <ostream>

namespace lvf::bench
{
SimulatedFrames::SimulatedFrames(
	const lvf::simulation::World& world, const lvf::simulation::CStereoLaserSimulator::TOptions& sensors)
{
	lvf::simulation::CStereoLaserSimulator sim(world, sensors);
	lvf::evaluation::RectifiedStereo stereo;
	for (size_t k = 0; k < sim.frameCount(); k++)
	{
		frames.push_back(sim.simulateNextFrame(true));	// the depth: for the seen truth scan
		frames.back().leftDepth.release();
		stereo.prepare(*frames.back().stereo, "frame");
		cv::Mat1b l, r;
		stereo.rectify(*frames.back().stereo, l, r);
		left.push_back(l.clone());
		right.push_back(r.clone());
	}
	geometry = stereo.geometry();
}

mrpt::obs::CObservation2DRangeScan::Ptr SimulatedFrames::dense(
	size_t k, lvf::depth::DenseMatcher matcher, const lvf::fusion::CLaserStereoFusion::TOptions& options,
	StageMedians* times, const std::string& name) const
{
	return denseFusedScan(
		left[k], right[k], geometry, options, options.depth.zMin, *frames[k].scan, matcher, times, name);
}

lvf::metrics::FusionScore SimulatedFrames::score(
	size_t k, const mrpt::obs::CObservation2DRangeScan& fused,
	const lvf::fusion::CLaserStereoFusion::TOptions& options) const
{
	const auto& frame = frames[k];
	const auto inView = lvf::metrics::bearingsInView(
		*frame.scan, frame.truthScan, *frame.stereo, options.band, options.depth.zMax);
	return lvf::metrics::scoreFusedScan(
		*frame.scan, fused, frame.truthScan, inView, options.depth.zMax, &frame.seenTruthScan);
}

void printScoreLine(std::ostream& out, const std::string& method, const lvf::metrics::FusionScore& s,
	const std::string& indent)
{
	out << std::fixed << std::setprecision(3) << indent << std::setw(22) << std::left << method << std::right
		<< " recall " << s.recall() << " of " << s.hidden << " (seen by both cameras " << s.seenRecall()
		<< ")  phantom rate " << s.phantomRate() << " of " << s.inView << "  median range error "
		<< s.rangeErrorMedian() << " m (hidden " << s.hiddenRangeErrorMedian() << " m)\n";
}

}  // namespace lvf::bench
