// lvf-bench, fusion: the box room's frames through CLaserStereoFusion,
// against OpenCV's StereoSGBM (3-way) and StereoBM over the whole image with
// a disparity range covering [z_min, z_max], each turned into the same fused
// scan: time per frame (benchmarks), the median time per frame of each stage
// of each method, and recall / phantom rate / range error of each against
// the truth scans (printed after the benchmarks, FusionBenchmarks.h).

#include "FusionBenchmarks.h"

#include "MethodRuns.h"
#include "SimulatedFrames.h"
#include "StageMedians.h"

#include <benchmark/benchmark.h>
#include <lvfusion/depth/DenseStereoBaseline.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/WorldLoader.h>

#include <iomanip>
#include <iostream>
#include <map>

using namespace lvf::simulation;

namespace lvf::bench
{
namespace
{
/** The box room's frames, simulated once, with what every method needs. */
struct FusionFixture
{
	static lvf::simulation::World boxRoom()
	{
		return loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml");
	}
	/** The same frames seen by a rig that needs rectifying (the right
	 * camera toed in and rolled, both with a lens): what the remap costs.
	 * Only the fusion takes them, so neither truth nor a rectified copy. */
	static std::vector<CStereoLaserSimulator::Frame> framesToRectify()
	{
		CStereoLaserSimulator::TOptions misaligned;
		misaligned.stereo.dist = {-0.15, 0.03, 0.001, -0.001, 0};
		misaligned.stereo.rightYawDeg = 1.5;
		misaligned.stereo.rightRollDeg = 0.7;
		CStereoLaserSimulator sim(boxRoom(), misaligned);
		std::vector<CStereoLaserSimulator::Frame> frames;
		for (size_t k = 0; k < sim.frameCount(); k++) frames.push_back(sim.simulateNextFrame(false));
		return frames;
	}

	SimulatedFrames run{boxRoom()};
	const std::vector<CStereoLaserSimulator::Frame> toRectify = framesToRectify();
	const std::vector<CStereoLaserSimulator::Frame>& frames = run.frames;
	lvf::fusion::CLaserStereoFusion::TOptions options;

	static FusionFixture& get()
	{
		static FusionFixture f;
		return f;
	}

	/** Fused scan of frame k by dense matching (MethodRuns.h). */
	mrpt::obs::CObservation2DRangeScan::Ptr dense(
		size_t k, lvf::depth::DenseMatcher m, lvf::bench::StageMedians* times = nullptr,
		const std::string& name = {}) const
	{
		return run.dense(k, m, options, times, name);
	}
};

void BM_Fusion_BoxRoom(benchmark::State& state)
{
	auto& f = FusionFixture::get();
	lvf::fusion::CLaserStereoFusion fusion(f.options);
	size_t k = 0;
	for (auto _ : state)
	{
		const auto& frame = f.frames[k++ % f.frames.size()];
		benchmark::DoNotOptimize(fusion.process(*frame.scan, *frame.stereo, "frame", frame.odometry).fused);
	}
}

template <lvf::depth::DenseMatcher M>
void BM_Dense_BoxRoom(benchmark::State& state)
{
	auto& f = FusionFixture::get();
	size_t k = 0;
	for (auto _ : state) benchmark::DoNotOptimize(f.dense(k++ % f.frames.size(), M));
}
void BM_SGBM_BoxRoom(benchmark::State& s) { BM_Dense_BoxRoom<lvf::depth::DenseMatcher::SemiGlobal>(s); }
void BM_BM_BoxRoom(benchmark::State& s) { BM_Dense_BoxRoom<lvf::depth::DenseMatcher::Block>(s); }

BENCHMARK(BM_Fusion_BoxRoom)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_SGBM_BoxRoom)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_BM_BoxRoom)->Unit(benchmark::kMillisecond)->MinTime(2.0);


}  // namespace

void printStageMedians(int passes)
{
	auto& f = FusionFixture::get();
	// The fusion as configured; with the model evaluated over the whole
	// image (the paper's way), which the faster grid evaluation replaces;
	// with every match searched at full resolution (no coarse-to-fine).
	auto wholeImage = f.options;
	wholeImage.evaluateSearchGridOnly = false;
	auto fullResolution = f.options;
	fullResolution.depth.coarseToFine = false;
	// And with each option that ships off the other way (what it costs).
	auto shifted = f.options;
	shifted.depth.shiftedWindows = !shifted.depth.shiftedWindows;
	auto subpixel = f.options;
	subpixel.depth.subpixelIterations = subpixel.depth.subpixelIterations > 0 ? 0 : 2;
	auto memory = f.options;
	memory.memory.maxTravel = memory.memory.maxTravel > 0 ? 0 : 1.5;
	auto nearestFirst = f.options;
	nearestFirst.depth.nearestFirstLevels = nearestFirst.depth.nearestFirstLevels > 0 ? 0 : 2;
	const std::vector<std::pair<std::string, lvf::fusion::CLaserStereoFusion::TOptions>> variants{
		{kFusionName, f.options}, {"fusion, whole-image eval", wholeImage},
		{"fusion, full-res search", fullResolution},
		{shifted.depth.shiftedWindows ? "fusion, shifted windows on" : "fusion, shifted windows off", shifted},
		{subpixel.depth.subpixelIterations > 0 ? "fusion, sub-pixel LK on" : "fusion, sub-pixel LK off", subpixel},
		{memory.memory.maxTravel > 0 ? "fusion, point memory on" : "fusion, point memory off", memory},
		{nearestFirst.depth.nearestFirstLevels > 0 ? "fusion, nearest first on" : "fusion, nearest first off",
			nearestFirst}};
	std::vector<lvf::fusion::CLaserStereoFusion> fusions;
	for (const auto& v : variants) fusions.emplace_back(v.second);
	// Every method above on one thread; the fusion as configured and SGBM
	// (which runs its rows on OpenCV's threads too) also on every core, for
	// what a robot's computer gives them.
	const int cores = cv::getNumberOfCPUs();
	const std::string threadsLabel = ", " + std::to_string(cores) + " threads";
	const std::string fusionOnCores = "fusion" + threadsLabel, sgbmOnCores = kSgbmName + threadsLabel;
	lvf::fusion::CLaserStereoFusion parallelFusion(f.options), fusionToRectify(f.options);
	const std::string toRectify = "fusion, a rig to rectify";
	auto onCores = [&](auto run) {
		cv::setNumThreads(cores);
		run();
		cv::setNumThreads(1);
	};
	lvf::bench::StageMedians medians;
	// Each method over every frame in turn, pass by pass (SeededRooms.cpp
	// says why).
	auto everyFrame = [&](auto run) {
		for (size_t k = 0; k < f.frames.size(); k++) run(k);
	};
	for (int pass = 0; pass < passes; pass++)
	{
		for (size_t i = 0; i < fusions.size(); i++)
			everyFrame([&](size_t k) {
				const auto& frame = f.frames[k];
				recordFusionTimes(medians, variants[i].first,
					fusions[i].process(*frame.scan, *frame.stereo, "frame", frame.odometry).times);
			});
		everyFrame([&](size_t k) {
			const auto& turned = f.toRectify[k];
			recordFusionTimes(
				medians, toRectify, fusionToRectify.process(*turned.scan, *turned.stereo, "frame", turned.odometry).times);
		});
		for (const auto& [matcher, name] : kDenseMethods)
			everyFrame([&, &matcher = matcher, &name = name](size_t k) { f.dense(k, matcher, &medians, name); });
		if (cores > 1)
			onCores([&] {
				everyFrame([&](size_t k) {
					const auto& frame = f.frames[k];
					recordFusionTimes(medians, fusionOnCores,
						parallelFusion.process(*frame.scan, *frame.stereo, "frame", frame.odometry).times);
				});
				everyFrame([&](size_t k) { f.dense(k, lvf::depth::DenseMatcher::SemiGlobal, &medians, sgbmOnCores); });
			});
	}
	std::cout << "\nMedian time per frame and stage [ms] on the box room (" << passes << " x "
			  << f.frames.size() << " frames, " << f.run.left.front().cols << "x" << f.run.left.front().rows
			  << ", one thread unless said, each method over all frames in turn):\n";
	medians.print(std::cout, kSgbmName);
	std::cout << std::fixed << std::setprecision(2) << "  (a rig to rectify: its right camera toed in 1.5 deg and rolled 0.7, "
			  << "both with a lens; the dense methods above match the pairs already rectified, and would pay the "
			  << medians.median(toRectify, "rectify") << " ms of the remap as well)\n";
	if (cores > 1)
		std::cout << std::fixed << std::setprecision(2) << "  on " << cores << " threads: the fusion "
				  << medians.medianTotal(kFusionName) / medians.medianTotal(fusionOnCores)
				  << "x its single-thread speed, SGBM "
				  << medians.medianTotal(kSgbmName) / medians.medianTotal(sgbmOnCores)
				  << "x; the fusion "
				  << medians.medianTotal(sgbmOnCores) / medians.medianTotal(fusionOnCores)
				  << "x faster than SGBM\n";
}

void printAccuracy()
{
	auto& f = FusionFixture::get();
	lvf::fusion::CLaserStereoFusion fusion(f.options);
	std::map<std::string, lvf::metrics::FusionScore> scores;
	for (size_t k = 0; k < f.frames.size(); k++)
	{
		const auto& frame = f.frames[k];
		auto score = [&](const mrpt::obs::CObservation2DRangeScan& fused) { return f.run.score(k, fused, f.options); };
		scores[kFusionName].add(score(*fusion.process(*frame.scan, *frame.stereo, "frame", frame.odometry).fused));
		scores[kSgbmName].add(score(*f.dense(k, lvf::depth::DenseMatcher::SemiGlobal)));
		scores[kBmName].add(score(*f.dense(k, lvf::depth::DenseMatcher::Block)));
		scores["laser alone"].add(score(*frame.scan));
	}
	std::cout << "\nAccuracy on the box room (" << f.frames.size()
			  << " frames, against the simulator's truth scans):\n";
	for (const auto& [name, s] : scores) printScoreLine(std::cout, name, s);
}

}  // namespace lvf::bench
