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
//   Real images the Middlebury scenes with a floor (RealScenes.cpp): the
//               fusion, SGBM and BM per scene, time and accuracy.
//   Seeded rooms with --random-rooms FIRST-LAST (SeededRooms.cpp): the box
//               room's comparison repeated on lvf-simulate's random rooms.
//   VFH         one VFH+ cycle on the default window of a 10 cm grid, and
//               CHolonomicVFH against MRPT's CHolonomicVFF / CHolonomicND on
//               the same TP-obstacles.
// Each group in its own file (SimulationBenchmarks.cpp, PlanningBenchmarks.cpp,
// FusionBenchmarks.cpp, VfhBenchmarks.cpp); this one reports the ratios.
// Everything runs on one thread (cv::setNumThreads(1)), but for two rows of
// the stage table: the fusion and SGBM again with OpenCV's threads on every
// core (both split their rows among them).

#include "BenchOptions.h"
#include "FusionBenchmarks.h"
#include "RealScenes.h"
#include "SeededRooms.h"

#include <benchmark/benchmark.h>
#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/ProcessMemory.h>
#include <opencv2/core/utility.hpp>

#include <iomanip>
#include <iostream>
#include <cstring>
#include <map>
#include <string>
#include <tuple>
#include <unistd.h>

namespace
{
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
	lvf::bench::OwnOptions own;
	try
	{
		own = lvf::bench::takeOwnOptions(argc, argv);
	}
	catch (const lvf::common::InputError& e)
	{
		std::cerr << "lvf-bench: " << e.what() << "\n";
		return lvf::common::kExitBadInput;
	}
	for (int i = 1; i < argc; i++)
		if (std::strcmp(argv[i], "--help") == 0) lvf::bench::printOwnHelp(std::cout);
	benchmark::Initialize(&argc, argv);
	if (benchmark::ReportUnrecognizedArguments(argc, argv)) return lvf::common::kExitBadInput;
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
	if (own.tables)
	{
		lvf::bench::printStageMedians(3);
		lvf::bench::printAccuracy();
		lvf::bench::printRealScenes(own.middlebury, 5);
		if (own.randomRooms) lvf::bench::printSeededRooms(own.randomRooms->first, own.randomRooms->second, 3);
	}
	benchmark::Shutdown();
	return 0;
}
