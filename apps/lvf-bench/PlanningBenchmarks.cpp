// lvf-bench, planning: value iteration (lvf::planning) on a 500x500 grid with
// clutter, corner to corner, against MRPT's PlannerSimple2D (wavefront) on
// the same grid and robot radius.

#include <benchmark/benchmark.h>
#include <lvfusion/planning/ValueIterationPlanner.h>
#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/random/RandomGenerators.h>

#include <deque>

namespace
{
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

}  // namespace
