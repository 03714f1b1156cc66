// lvf-bench: Google Benchmark figures for lvfusion, each reported beside a
// baseline measured in the same process (ratios, not absolute promises).
//
//   Simulation  one frame of the Fig. 7 box room: a 640x480 stereo pair with
//               tile culling + a 181-ray laser scan + its truth scan, against
//               the same frame rendered brute force (every box, every ray).

#include <benchmark/benchmark.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/GroundTruth.h>
#include <lvfusion/simulation/WorldLoader.h>

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
		left + mrpt::poses::CPose3D(o.baseline, 0, 0, 0, 0, 0);
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
			m_msPerIteration[r.run_name.function_name] = r.GetAdjustedRealTime();
	}
	std::map<std::string, double> m_msPerIteration;
};

/** (benchmark, its baseline, what the figure means) */
const std::vector<std::tuple<std::string, std::string, std::string>> kComparisons{
	{"BM_SimulateFrame_BoxRoom", "BM_SimulateFrame_BoxRoom_BruteForce",
	 "simulated frame (stereo pair + scan), tile culling vs brute force"},
};

}  // namespace

int main(int argc, char** argv)
{
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
		std::cout << std::fixed << std::setprecision(2) << "  " << meaning << ": "
				  << a->second << " ms vs " << b->second << " ms = "
				  << b->second / a->second << "x faster\n";
	}
	benchmark::Shutdown();
	return 0;
}
