// VFH+ cycle figures for lvf-bench (see main.cpp for the reporting):
//   BM_VfhCycle_GridWindow  one VFH+ cycle of the grid engine on the default
//                           active window (1.6 m radius over a 10 cm grid):
//                           window extraction + histograms + decision;
//                           ..._Full: every cell of the window occupied, the
//                           most a cycle can have to do
//   BM_Holonomic_VFH/VFF/ND MRPT's holonomic-method interface on one and the
//                           same input (121 TP-obstacles cast in that grid):
//                           CHolonomicVFH against MRPT's CHolonomicVFF and
//                           CHolonomicND, the baselines;
//   BM_VfhCycle_TpCells     the VFH+ cycle alone on CHolonomicVFH's cells
//                           of that input: what the adapter and the log
//                           record add is the difference.

#include <benchmark/benchmark.h>
#include <lvfusion/vfh/CHolonomicVFH.h>
#include <mrpt/nav/holonomic/CHolonomicND.h>
#include <mrpt/nav/holonomic/CHolonomicVFF.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>

namespace
{
/** A 10 cm grid: a wall and three boxes within the default window of a
 * robot at the origin, heading +x, target 4 m ahead behind a box. */
struct VfhFixture
{
	mrpt::maps::COccupancyGridMap2D grid{-6, 6, -6, 6, 0.10f};
	mrpt::maps::COccupancyGridMap2D full{-6, 6, -6, 6, 0.10f};
	mrpt::nav::CAbstractHolonomicReactiveMethod::NavInput tp;

	VfhFixture()
	{
		grid.fill(0.9f);  // p(free)
		auto box = [&](double x0, double y0, double x1, double y1) {
			for (int cx = grid.x2idx(x0); cx <= grid.x2idx(x1); cx++)
				for (int cy = grid.y2idx(y0); cy <= grid.y2idx(y1); cy++) grid.setCell(cx, cy, 0.0f);
		};
		box(-2.0, 1.5, 2.0, 1.6);
		box(1.0, -0.3, 1.3, 0.4);
		box(-0.8, -1.2, -0.5, -0.6);
		box(0.2, -1.4, 1.2, -1.1);
		// TP-obstacles of straight paths: a 360 deg scan of 121 rays,
		// ranges normalised by a 4 m reference distance.
		mrpt::obs::CObservation2DRangeScan scan;
		scan.aperture = 2 * M_PI;
		scan.maxRange = 4.0;
		grid.laserScanSimulator(scan, mrpt::poses::CPose2D(0, 0, 0), 0.5f, 121);
		for (size_t i = 0; i < scan.getScanSize(); i++)
			tp.obstacles.push_back(scan.getScanRangeValidity(i) ? scan.getScanRange(i) / 4.0 : 1.0);
		tp.targets = {{1.0, 0.0}};
		full.fill(0.0f);
	}
	static VfhFixture& get()
	{
		static VfhFixture f;
		return f;
	}
};

void vfhCycle(benchmark::State& state, const mrpt::maps::COccupancyGridMap2D& grid)
{
	lvf::vfh::VfhPlus vfh;
	size_t cells = 0;
	for (auto _ : state)
	{
		const auto window = lvf::vfh::activeWindow(grid, {0, 0}, vfh.parameters().windowRadius);
		benchmark::DoNotOptimize(vfh.step(window, 0.0, 0.0).direction);
		cells = window.size();
	}
	state.counters["obstacle_cells"] = double(cells);
}
void BM_VfhCycle_GridWindow(benchmark::State& s) { vfhCycle(s, VfhFixture::get().grid); }
void BM_VfhCycle_GridWindow_Full(benchmark::State& s) { vfhCycle(s, VfhFixture::get().full); }

template <typename Method>
void holonomic(benchmark::State& state)
{
	auto& f = VfhFixture::get();
	Method method;
	mrpt::nav::CAbstractHolonomicReactiveMethod::NavOutput out;
	for (auto _ : state)
	{
		method.navigate(f.tp, out);
		benchmark::DoNotOptimize(out.desiredDirection);
	}
}
void BM_VfhCycle_TpCells(benchmark::State& state)
{
	const auto cells = lvf::vfh::CHolonomicVFH::tpObstacleCells(VfhFixture::get().tp);
	lvf::vfh::VfhPlus vfh(lvf::vfh::CHolonomicVFH::TOptions::tpSpaceDefaults());
	for (auto _ : state) benchmark::DoNotOptimize(vfh.step(cells, 0.0, 0.0).direction);
}
void BM_Holonomic_VFH(benchmark::State& s) { holonomic<lvf::vfh::CHolonomicVFH>(s); }
void BM_Holonomic_VFF(benchmark::State& s) { holonomic<mrpt::nav::CHolonomicVFF>(s); }
void BM_Holonomic_ND(benchmark::State& s) { holonomic<mrpt::nav::CHolonomicND>(s); }
}  // namespace

BENCHMARK(BM_VfhCycle_GridWindow)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_VfhCycle_GridWindow_Full)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_VfhCycle_TpCells)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_Holonomic_VFH)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_Holonomic_VFF)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
BENCHMARK(BM_Holonomic_ND)->Unit(benchmark::kMicrosecond)->MinTime(1.0);
