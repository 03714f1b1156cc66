// lvf-bench: Google Benchmark figures for lvfusion, each reported beside a
// baseline measured in the same process (ratios, not absolute promises).
//
//   Simulation  one frame of the Fig. 7 box room: a 640x480 stereo pair with
//               tile culling + a 181-ray laser scan + its truth scan, against
//               the same frame rendered brute force (every box, every ray).
//   Planning    value iteration (lvf::planning) on a 500x500 grid with
//               clutter, corner to corner, against MRPT's PlannerSimple2D
//               (wavefront) on the same grid and robot radius.
//   Fusion      the box room's frames through CLaserStereoFusion, against
//               OpenCV's StereoSGBM (3-way) and StereoBM over the whole image
//               with a disparity range covering [z_min, z_max], each turned
//               into the same fused scan; time per frame, the median time
//               per frame of each stage of each method, and recall /
//               phantom rate / range error of each against the truth scans.
//   VFH         one VFH+ cycle on the default window of a 10 cm grid, and
//               CHolonomicVFH against MRPT's CHolonomicVFF / CHolonomicND on
//               the same TP-obstacles (VfhBenchmarks.cpp).
// Everything runs on one thread (cv::setNumThreads(1)), but for two rows of
// the stage table: the fusion and SGBM again with OpenCV's threads on every
// core (both split their rows among them).

#include <benchmark/benchmark.h>
#include <lvfusion/common/ProcessMemory.h>
#include <lvfusion/depth/DenseStereoBaseline.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/planning/ValueIterationPlanner.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/GroundTruth.h>
#include <lvfusion/simulation/WorldLoader.h>

#include "StageMedians.h"

#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/random/RandomGenerators.h>

#include <chrono>
#include <iomanip>
#include <iostream>
#include <map>
#include <unistd.h>

using namespace lvf::simulation;

namespace
{
struct BoxRoomFixture
{
	World world = loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml");
	CStereoLaserSimulator::TOptions options;
	WorldGeometry geometry{world};
	SimulatedStereoRig rig{options.stereo};
	SimulatedLaser laser{options.laser};
	mrpt::poses::CPose3D robot{mrpt::poses::CPose2D(world.path.front())};

	static BoxRoomFixture& get()
	{
		static BoxRoomFixture f;
		return f;
	}
};

void renderFrame(benchmark::State& state, bool bruteForce)
{
	auto& f = BoxRoomFixture::get();
	const auto& o = f.options.stereo;
	const mrpt::poses::CPose3D left = f.robot + o.leftCameraPose();
	const mrpt::poses::CPose3D right =
		left + o.rightCameraPose();
	cv::Mat1b imgL, imgR;
	uint64_t seed = 0;
	for (auto _ : state)
	{
		seed++;
		f.rig.renderCamera(f.geometry, left, f.rig.leftRays(), o.leftGain, o.leftNoiseStd, 2 * seed, imgL, nullptr, bruteForce);
		f.rig.renderCamera(f.geometry, right, f.rig.rightRays(), o.rightGain, o.rightNoiseStd, 2 * seed + 1, imgR, nullptr, bruteForce);
		const auto scan = f.laser.scan(f.geometry, f.robot, seed, {});
		const auto truth = truthScan(f.world, f.robot, *scan);
		benchmark::DoNotOptimize(truth.data());
		benchmark::DoNotOptimize(imgR.data);
	}
}

void BM_SimulateFrame_BoxRoom(benchmark::State& s) { renderFrame(s, false); }
void BM_SimulateFrame_BoxRoom_BruteForce(benchmark::State& s) { renderFrame(s, true); }

BENCHMARK(BM_SimulateFrame_BoxRoom)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_SimulateFrame_BoxRoom_BruteForce)->Unit(benchmark::kMillisecond)->MinTime(2.0);

/** 500 x 500 cells of 5 cm, observed free, with 150 seeded rectangular
 * obstacles (kept off the two corners the plans join). */
const mrpt::maps::COccupancyGridMap2D& clutteredGrid500()
{
	static const mrpt::maps::COccupancyGridMap2D grid = [] {
		mrpt::maps::COccupancyGridMap2D g(0, 25, 0, 25, 0.05f);
		g.fill(1.0f);
		auto& rng = mrpt::random::getRandomGenerator();
		rng.randomize(500);
		for (int k = 0; k < 150; k++)
		{
			const double x = rng.drawUniform(2, 22), y = rng.drawUniform(2, 22);
			const double w = rng.drawUniform(0.2, 2.0), h = rng.drawUniform(0.2, 2.0);
			for (double px = x; px <= x + w; px += 0.025)
				for (double py = y; py <= y + h; py += 0.025) g.setPos(px, py, 0.0f);
		}
		return g;
	}();
	return grid;
}
const mrpt::math::TPoint2D kPlanStart{1, 1}, kPlanGoal{24, 24};

void BM_ValueIteration_500x500(benchmark::State& state)
{
	const lvf::planning::ValueIterationPlanner planner;
	for (auto _ : state)
	{
		const auto r = planner.plan(clutteredGrid500(), kPlanStart, kPlanGoal);
		if (!r.found()) state.SkipWithError("no path");
		benchmark::DoNotOptimize(r.path.data());
	}
}

void BM_ValueIteration_500x500_GrownGridGiven(benchmark::State& state)
{
	const lvf::planning::ValueIterationPlanner planner;
	const lvf::planning::TraversableGrid grid(
		clutteredGrid500(), planner.options().robotRadius, planner.options().obstacleBelow);
	for (auto _ : state)
	{
		const auto r = planner.plan(grid, kPlanStart, kPlanGoal);
		if (!r.found()) state.SkipWithError("no path");
		benchmark::DoNotOptimize(r.path.data());
	}
}

void BM_PlannerSimple2D_500x500(benchmark::State& state)
{
	mrpt::nav::PlannerSimple2D planner;
	planner.robotRadius = static_cast<float>(lvf::planning::ValueIterationPlanner::TOptions().robotRadius);
	for (auto _ : state)
	{
		std::deque<mrpt::math::TPoint2D> path;
		bool notFound = true;
		planner.computePath(
			clutteredGrid500(), mrpt::poses::CPose2D(kPlanStart.x, kPlanStart.y, 0),
			mrpt::poses::CPose2D(kPlanGoal.x, kPlanGoal.y, 0), path, notFound);
		if (notFound) state.SkipWithError("no path");
		benchmark::DoNotOptimize(path.size());
	}
}

BENCHMARK(BM_ValueIteration_500x500)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_ValueIteration_500x500_GrownGridGiven)->Unit(benchmark::kMillisecond)->MinTime(2.0);
BENCHMARK(BM_PlannerSimple2D_500x500)->Unit(benchmark::kMillisecond)->MinTime(2.0);

/** The box room's frames, simulated once, with what every method needs. */
struct FusionFixture
{
	std::vector<CStereoLaserSimulator::Frame> frames;
	std::vector<cv::Mat1b> left, right;	 // rectified grey
	lvf::evaluation::RectifiedGeometry geometry;
	lvf::fusion::CLaserStereoFusion::TOptions options;

	FusionFixture()
	{
		World world = loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml");
		CStereoLaserSimulator sim(world, CStereoLaserSimulator::TOptions());
		lvf::evaluation::RectifiedStereo stereo;
		for (size_t k = 0; k < sim.frameCount(); k++)
		{
			frames.push_back(sim.simulateNextFrame(false));
			stereo.prepare(*frames.back().stereo, "frame");
			cv::Mat1b l, r;
			stereo.rectify(*frames.back().stereo, l, r);
			left.push_back(l.clone());
			right.push_back(r.clone());
		}
		geometry = stereo.geometry();
	}
	static FusionFixture& get()
	{
		static FusionFixture f;
		return f;
	}

	/** Fused scan of frame k by dense matching; with `times`, the time of
	 * its two stages (matching, disparity -> fused scan) recorded as `name`. */
	mrpt::obs::CObservation2DRangeScan::Ptr dense(
		size_t k, lvf::depth::DenseMatcher m, lvf::bench::StageMedians* times = nullptr,
		const std::string& name = {}) const
	{
		using Clock = std::chrono::steady_clock;
		auto ms = [](Clock::time_point a, Clock::time_point b) {
			return std::chrono::duration<double, std::milli>(b - a).count();
		};
		const auto t0 = Clock::now();
		const auto d = lvf::depth::denseDisparity(left[k], right[k], geometry, options.depth.zMin, m);
		const auto t1 = Clock::now();
		const auto points = lvf::depth::disparityToPoints(
			d, geometry, options.band, options.depth.zMin, options.depth.zMax, options.depth.pixelStride);
		const lvf::fusion::ScanFusion fusion(options.fusion);
		auto fused = lvf::fusion::ScanFusion::fuse(*frames[k].scan, fusion.visualRanges(*frames[k].scan, points));
		if (times)
		{
			times->add(name, "matching", ms(t0, t1));
			times->add(name, "to_scan", ms(t1, Clock::now()));
		}
		return fused;
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

const std::string kFusionName = "fusion (this paper)";
const std::string kSgbmName = "StereoSGBM 3-way";
const std::string kBmName = "StereoBM";

/** Median time per frame of every stage of every method, over `passes`
 * passes through the box room's frames (each method in turn per frame, so
 * that a busy spell of the machine hits them alike). */
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
	lvf::fusion::CLaserStereoFusion parallelFusion(f.options);
	auto onCores = [&](auto run) {
		cv::setNumThreads(cores);
		run();
		cv::setNumThreads(1);
	};
	lvf::bench::StageMedians medians;
	auto addFusionTimes = [&](const std::string& name, const lvf::fusion::CLaserStereoFusion::StageTimes& t) {
		for (const auto& [stage, ms] : {std::pair{"lines", t.lines}, {"model", t.model}, {"rectify", t.rectify},
				 {"evaluate", t.evaluate}, {"search", t.search}, {"fuse", t.fuse}})
			medians.add(name, stage, ms);
	};
	for (int pass = 0; pass < passes; pass++)
		for (size_t k = 0; k < f.frames.size(); k++)
		{
			const auto& frame = f.frames[k];
			for (size_t i = 0; i < fusions.size(); i++)
				addFusionTimes(variants[i].first, fusions[i].process(*frame.scan, *frame.stereo, "frame", frame.odometry).times);
			f.dense(k, lvf::depth::DenseMatcher::SemiGlobal, &medians, kSgbmName);
			f.dense(k, lvf::depth::DenseMatcher::Block, &medians, kBmName);
			if (cores > 1)
				onCores([&] {
					addFusionTimes(fusionOnCores,
						parallelFusion.process(*frame.scan, *frame.stereo, "frame", frame.odometry).times);
					f.dense(k, lvf::depth::DenseMatcher::SemiGlobal, &medians, sgbmOnCores);
				});
		}
	std::cout << "\nMedian time per frame and stage [ms] on the box room (" << passes << " x "
			  << f.frames.size() << " frames, " << f.left.front().cols << "x" << f.left.front().rows
			  << ", one thread unless said):\n";
	medians.print(std::cout, kSgbmName);
	if (cores > 1)
		std::cout << std::fixed << std::setprecision(2) << "  on " << cores << " threads: the fusion "
				  << medians.medianTotal(kFusionName) / medians.medianTotal(fusionOnCores)
				  << "x its single-thread speed, SGBM "
				  << medians.medianTotal(kSgbmName) / medians.medianTotal(sgbmOnCores)
				  << "x; the fusion "
				  << medians.medianTotal(sgbmOnCores) / medians.medianTotal(fusionOnCores)
				  << "x faster than SGBM\n";
}

/** Recall / phantom rate / range error of each method over all frames. */
void printAccuracy()
{
	auto& f = FusionFixture::get();
	lvf::fusion::CLaserStereoFusion fusion(f.options);
	std::map<std::string, lvf::metrics::FusionScore> scores;
	for (size_t k = 0; k < f.frames.size(); k++)
	{
		const auto& frame = f.frames[k];
		const auto inView = lvf::metrics::bearingsInView(
			*frame.scan, frame.truthScan, *frame.stereo, f.options.band, f.options.depth.zMax);
		auto score = [&](const mrpt::obs::CObservation2DRangeScan& fused) {
			return lvf::metrics::scoreFusedScan(*frame.scan, fused, frame.truthScan, inView, f.options.depth.zMax);
		};
		scores[kFusionName].add(score(*fusion.process(*frame.scan, *frame.stereo, "frame", frame.odometry).fused));
		scores[kSgbmName].add(score(*f.dense(k, lvf::depth::DenseMatcher::SemiGlobal)));
		scores[kBmName].add(score(*f.dense(k, lvf::depth::DenseMatcher::Block)));
		scores["laser alone"].add(score(*frame.scan));
	}
	std::cout << "\nAccuracy on the box room (" << f.frames.size()
			  << " frames, against the simulator's truth scans):\n";
	for (const auto& [name, s] : scores)
		std::cout << std::fixed << std::setprecision(3) << "  " << std::setw(22) << std::left << name
				  << " recall " << s.recall() << "  phantom rate " << s.phantomRate()
				  << "  median range error " << s.rangeErrorMedian << " m (hidden "
				  << s.hiddenRangeErrorMedian << " m)\n";
}

/** Console output as usual, plus the real time of every run kept by name. */
class RecordingReporter : public benchmark::ConsoleReporter
{
   public:
	RecordingReporter()
		: ConsoleReporter(::isatty(STDOUT_FILENO) ? OO_ColorTabular : OO_Tabular)
	{
	}
	void ReportRuns(const std::vector<Run>& runs) override
	{
		ConsoleReporter::ReportRuns(runs);
		for (const auto& r : runs)
			m_msPerIteration[r.run_name.function_name] =
				r.GetAdjustedRealTime() / benchmark::GetTimeUnitMultiplier(r.time_unit) * 1e3;
	}
	std::map<std::string, double> m_msPerIteration;
};

/** (benchmark, its baseline, what the figure means) */
const std::vector<std::tuple<std::string, std::string, std::string>> kComparisons{
	{"BM_SimulateFrame_BoxRoom", "BM_SimulateFrame_BoxRoom_BruteForce",
	 "simulated frame (stereo pair + scan), tile culling vs brute force"},
	{"BM_ValueIteration_500x500", "BM_PlannerSimple2D_500x500",
	 "planning on a 500x500 grid, value iteration vs MRPT's PlannerSimple2D"},
	{"BM_Fusion_BoxRoom", "BM_SGBM_BoxRoom", "fused scan per frame, this paper's fusion vs StereoSGBM"},
	{"BM_Fusion_BoxRoom", "BM_BM_BoxRoom", "fused scan per frame, this paper's fusion vs StereoBM"},
	{"BM_Holonomic_VFH", "BM_Holonomic_VFF", "holonomic step, CHolonomicVFH vs MRPT's CHolonomicVFF"},
	{"BM_Holonomic_VFH", "BM_Holonomic_ND", "holonomic step, CHolonomicVFH vs MRPT's CHolonomicND"},
};

}  // namespace

int main(int argc, char** argv)
{
	cv::setNumThreads(1);  // single-thread figures, for every method alike
	lvf::common::retainLargeAllocations();	// as the apps do (ProcessMemory.h)
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
	RecordingReporter reporter;
	benchmark::RunSpecifiedBenchmarks(&reporter);

	std::cout << "\nRatios against baselines run in this process (one core):\n";
	for (const auto& [name, baseline, meaning] : kComparisons)
	{
		const auto a = reporter.m_msPerIteration.find(name);
		const auto b = reporter.m_msPerIteration.find(baseline);
		if (a == reporter.m_msPerIteration.end() || b == reporter.m_msPerIteration.end())
			continue;
		const double ratio = b->second / a->second;
		std::cout << std::fixed << std::setprecision(4) << "  " << meaning << ": "
				  << a->second << " ms vs " << b->second << " ms = " << std::setprecision(2)
				  << (ratio >= 1 ? ratio : 1 / ratio) << (ratio >= 1 ? "x faster\n" : "x slower\n");
	}
	if (const auto vfh = reporter.m_msPerIteration.find("BM_VfhCycle_GridWindow");
		vfh != reporter.m_msPerIteration.end())
		std::cout << std::setprecision(4) << "  VFH+ cycle (window + histograms + decision) on the default "
				  << "1.6 m window of a 10 cm grid: " << vfh->second << " ms (issue 4 asks < 1 ms)\n";
	if (const auto full = reporter.m_msPerIteration.find("BM_VfhCycle_GridWindow_Full");
		full != reporter.m_msPerIteration.end())
		std::cout << "  ... with every cell of the window occupied: " << full->second << " ms\n";
	printStageMedians(3);
	printAccuracy();
	benchmark::Shutdown();
	return 0;
}
