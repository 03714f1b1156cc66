// lvf-bench, simulation: one frame of the Fig. 7 box room (a 640x480 stereo
// pair with tile culling + a 181-ray laser scan + its truth scan) against the
// same frame rendered brute force (every box, every ray).

#include <benchmark/benchmark.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/GroundTruth.h>
#include <lvfusion/simulation/WorldLoader.h>

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

}  // namespace
