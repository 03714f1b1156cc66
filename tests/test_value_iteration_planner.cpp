// Value-iteration planning (libs/planning) on grids whose answers geometry
// gives: an empty room, a wall with a gap, a gap too narrow for the robot,
// bad starts and goals; the value function checked to be the Bellman fixed
// point; and the same maps planned by MRPT's PlannerSimple2D.

#include <gtest/gtest.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/planning/PathMetrics.h>
#include <lvfusion/planning/ValueIterationPlanner.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/nav/planners/PlannerSimple2D.h>
#include <mrpt/random/RandomGenerators.h>

#include <cmath>

using namespace lvf::planning;
using mrpt::maps::COccupancyGridMap2D;
using mrpt::math::TPoint2D;

namespace
{
constexpr double kRes = 0.05;

/** A 10 m x 10 m grid, every cell observed free. */
COccupancyGridMap2D emptyRoom()
{
	COccupancyGridMap2D g(0, 10, 0, 10, kRes);
	g.fill(1.0f);
	return g;
}

/** Marks the rectangle [x0,x1] x [y0,y1] occupied. */
void addBlock(COccupancyGridMap2D& g, double x0, double x1, double y0, double y1)
{
	for (double x = x0; x <= x1; x += kRes / 2)
		for (double y = y0; y <= y1; y += kRes / 2) g.setPos(x, y, 0.0f);
}

/** A wall across the room at x = 5, open for y in [gapLow, gapHigh]. */
COccupancyGridMap2D wallWithGap(double gapLow, double gapHigh)
{
	auto g = emptyRoom();
	addBlock(g, 4.9, 5.1, 0, gapLow);
	addBlock(g, 4.9, 5.1, gapHigh, 10);
	return g;
}

/** 8-connected grid distance between the cells of a and b. */
double octileDistance(const TraversableGrid& grid, const TPoint2D& a, const TPoint2D& b)
{
	const auto ca = grid.cellOf(a), cb = grid.cellOf(b);
	const double dx = std::abs(ca.x - cb.x), dy = std::abs(ca.y - cb.y);
	return kRes * (std::max(dx, dy) - std::min(dx, dy) + std::sqrt(2.0) * std::min(dx, dy));
}

std::vector<TPoint2D> planSimple2D(const COccupancyGridMap2D& g, TPoint2D a, TPoint2D b, double radius, bool& found)
{
	mrpt::nav::PlannerSimple2D planner;
	planner.robotRadius = static_cast<float>(radius);
	planner.minStepInReturnedPath = 0;	// every cell, to compare lengths fairly
	std::deque<TPoint2D> path;
	bool notFound = true;
	planner.computePath(g, mrpt::poses::CPose2D(a.x, a.y, 0), mrpt::poses::CPose2D(b.x, b.y, 0), path, notFound);
	found = !notFound;
	return {path.begin(), path.end()};
}
}  // namespace

TEST(ValueIterationPlanner, EmptyRoomPathIsTheStraightLineUpToTheGrid)
{
	const auto g = emptyRoom();
	const ValueIterationPlanner planner;
	const TraversableGrid grid(g, planner.options().robotRadius, planner.options().obstacleBelow);
	const TPoint2D start{1.02, 1.13}, goal{8.71, 6.04};
	const auto r = planner.plan(grid, start, goal);
	ASSERT_TRUE(r.found()) << describe(r.outcome);
	EXPECT_TRUE(r.converged);
	// The cost-to-go is the exact 8-connected distance between the cells.
	EXPECT_NEAR(r.costToGo, octileDistance(grid, start, goal), 1e-3);
	// The path: no shorter than the straight line, no longer than the
	// 8-connected detour bound (1/cos(22.5 deg) = 1.0824) plus the two
	// half-cell stubs from the exact start and goal to their cell centres.
	const double straight = std::hypot(goal.x - start.x, goal.y - start.y);
	const double length = pathLength(r.path);
	EXPECT_GE(length, straight);
	EXPECT_LE(length, 1.0824 * straight + 2 * kRes * std::sqrt(2.0));
	EXPECT_NEAR(r.path.front().x, start.x, 1e-12);
	EXPECT_NEAR(r.path.back().y, goal.y, 1e-12);
	std::printf("empty room: straight %.3f m, path %.3f m, %zu sweeps\n", straight, length, r.sweeps);
}

TEST(ValueIterationPlanner, WallWithGapPathGoesThroughTheGap)
{
	const auto g = wallWithGap(7.0, 8.0);
	const ValueIterationPlanner planner;
	const TraversableGrid grid(g, planner.options().robotRadius, planner.options().obstacleBelow);
	const TPoint2D start{2, 2}, goal{8, 2};
	const auto r = planner.plan(grid, start, goal);
	ASSERT_TRUE(r.found()) << describe(r.outcome);
	// Where the path crosses the wall it is inside the gap.
	for (size_t i = 0; i + 1 < r.path.size(); i++)
		if ((r.path[i].x - 5) * (r.path[i + 1].x - 5) <= 0)
		{
			EXPECT_GT(r.path[i].y, 7.0);
			EXPECT_LT(r.path[i].y, 8.0);
		}
	// Never nearer an obstacle cell than the robot radius.
	EXPECT_GE(minimumClearance(r.path, grid), planner.options().robotRadius);
	// No shorter than the way through the wall's middle just above its
	// end grown by the radius, (5, 7 + radius); no longer than the
	// 8-connected bound on a way round the grown wall end, clear of it:
	// via (4.55, 7.4) and (5.45, 7.4).
	const double radius = planner.options().robotRadius;
	auto dist = [](TPoint2D a, TPoint2D b) { return std::hypot(a.x - b.x, a.y - b.y); };
	const TPoint2D corner{5, 7.0 + radius}, a{4.55, 7.4}, b{5.45, 7.4};
	const double viaCorner = dist(start, corner) + dist(corner, goal);
	const double roundTheEnd = dist(start, a) + dist(a, b) + dist(b, goal);
	const double length = pathLength(r.path);
	EXPECT_GE(length, viaCorner);
	EXPECT_LE(length, 1.0824 * roundTheEnd + 2 * kRes * std::sqrt(2.0));
	std::printf("wall with gap: bounds %.3f .. %.3f m, path %.3f m, %zu sweeps\n", viaCorner,
				1.0824 * roundTheEnd + 2 * kRes * std::sqrt(2.0), length, r.sweeps);
}

TEST(ValueIterationPlanner, GapNarrowerThanTheRobotIsUnreachable)
{
	// 0.5 m gap, 0.6 m robot: grown by the radius it closes.
	const auto g = wallWithGap(7.0, 7.5);
	const ValueIterationPlanner planner;
	const auto r = planner.plan(g, {2, 2}, {8, 2});
	EXPECT_EQ(r.outcome, PlanOutcome::Unreachable);
	EXPECT_TRUE(r.converged);
	EXPECT_TRUE(r.path.empty());
	// A smaller robot passes.
	ValueIterationPlanner::TOptions small;
	small.robotRadius = 0.15;
	EXPECT_TRUE(ValueIterationPlanner(small).plan(g, {2, 2}, {8, 2}).found());
}

TEST(ValueIterationPlanner, ASweepBoundTooLowIsToldApartFromNoPath)
{
	// Round the end of a wall the values need more than one sweep: with
	// max_sweeps 1 there is no path yet, which is no proof there is none.
	const auto g = wallWithGap(7.0, 8.0);
	ValueIterationPlanner::TOptions one;
	one.maxSweeps = 1;
	const auto r = ValueIterationPlanner(one).plan(g, {2, 2}, {8, 2});
	EXPECT_EQ(r.outcome, PlanOutcome::SweepsExhausted) << describe(r.outcome);
	EXPECT_FALSE(r.converged);
	EXPECT_TRUE(ValueIterationPlanner().plan(g, {2, 2}, {8, 2}).found());
}

TEST(ValueIterationPlanner, BadStartsAndGoalsAreReported)
{
	const auto g = wallWithGap(7.0, 8.0);
	const ValueIterationPlanner planner;
	EXPECT_EQ(planner.plan(g, {-1, 2}, {8, 2}).outcome, PlanOutcome::StartOutsideMap);
	EXPECT_EQ(planner.plan(g, {2, 2}, {8, 10.5}).outcome, PlanOutcome::GoalOutsideMap);
	EXPECT_EQ(planner.plan(g, {5, 2}, {8, 2}).outcome, PlanOutcome::StartBlocked);	// in the wall
	EXPECT_EQ(planner.plan(g, {2, 2}, {5.35, 2}).outcome, PlanOutcome::GoalBlocked);  // within the radius
	EXPECT_TRUE(planner.plan(g, {2, 2}, {5.5, 2}).found());	 // just clear of it
	// Unobserved cells (0.5) are traversable with the default threshold,
	// obstacles with one above 0.5.
	COccupancyGridMap2D unknown(0, 10, 0, 10, kRes);
	EXPECT_TRUE(planner.plan(unknown, {2, 2}, {8, 2}).found());
	ValueIterationPlanner::TOptions strict;
	strict.obstacleBelow = 0.51;
	EXPECT_EQ(ValueIterationPlanner(strict).plan(unknown, {2, 2}, {8, 2}).outcome, PlanOutcome::StartBlocked);
}

TEST(ValueIterationPlanner, ValueFunctionIsTheBellmanFixedPoint)
{
	// Random clutter: the value of every reachable cell equals its best
	// one-step lookahead, and unreachable cells have no traversable
	// neighbour with a finite value.
	auto g = emptyRoom();
	auto& rng = mrpt::random::getRandomGenerator();
	rng.randomize(7);
	for (int k = 0; k < 40; k++)
	{
		const double x = rng.drawUniform(0.5, 9.0), y = rng.drawUniform(0.5, 9.0);
		addBlock(g, x, x + rng.drawUniform(0.1, 1.0), y, y + rng.drawUniform(0.1, 1.0));
	}
	const TraversableGrid grid(g, 0.3, 0.5);
	const GridCell goal = grid.cellOf({9.5, 9.5});
	ASSERT_TRUE(grid.isTraversable(goal));
	const auto vf = computeValueFunction(grid, goal, 100000, 0);
	ASSERT_TRUE(vf.converged);
	const cv::Mat1f& v = vf.value;
	size_t reachable = 0;
	for (int y = 0; y < v.rows; y++)
		for (int x = 0; x < v.cols; x++)
		{
			if (!grid.isTraversable({x, y}) || GridCell{x, y} == goal) continue;
			float best = INFINITY;
			for (int dy = -1; dy <= 1; dy++)
				for (int dx = -1; dx <= 1; dx++)
				{
					const GridCell n{x + dx, y + dy};
					if ((!dx && !dy) || n.x < 0 || n.y < 0 || n.x >= v.cols || n.y >= v.rows) continue;
					if (!grid.isTraversable(n)) continue;
					if (dx && dy && (!grid.isTraversable({x + dx, y}) || !grid.isTraversable({x, y + dy}))) continue;
					const float step = float(kRes);	 // the planner's float costs
					best = std::min(best, (dx && dy ? step * std::sqrt(2.0f) : step) + v(n.y, n.x));
				}
			if (std::isfinite(v(y, x))) reachable++;
			ASSERT_EQ(v(y, x), best) << "cell " << x << "," << y;
		}
	EXPECT_GT(reachable, v.total() / 2);
	std::printf("clutter: %zu reachable cells, converged in %zu sweeps\n", reachable, vf.sweeps);
}

TEST(ValueIterationPlanner, AgreesWithMrptPlannerSimple2D)
{
	struct Case
	{
		const char* name;
		COccupancyGridMap2D map;
		TPoint2D start, goal;
	};
	auto clutter = emptyRoom();
	addBlock(clutter, 3, 4, 1, 6);
	addBlock(clutter, 6, 7, 4, 9.5);
	addBlock(clutter, 1, 2.5, 7, 8);
	const std::vector<Case> cases{
		{"empty room", emptyRoom(), {1, 1}, {8.7, 6}},
		{"wall with gap", wallWithGap(7.0, 8.0), {2, 2}, {8, 2}},
		{"clutter", clutter, {1, 1}, {9, 9}}};
	const ValueIterationPlanner planner;
	const double radius = planner.options().robotRadius;
	for (const auto& c : cases)
	{
		const TraversableGrid grid(c.map, radius, planner.options().obstacleBelow);
		const auto ours = planner.plan(grid, c.start, c.goal);
		bool mrptFound = false;
		const auto theirs = planSimple2D(c.map, c.start, c.goal, radius, mrptFound);
		ASSERT_TRUE(ours.found()) << c.name;
		ASSERT_TRUE(mrptFound) << c.name;
		const double a = pathLength(ours.path), b = pathLength(theirs);
		const double ca = minimumClearance(ours.path, grid), cb = minimumClearance(theirs, grid);
		std::printf("%s: value iteration %.3f m (clearance %.3f m), PlannerSimple2D %.3f m (clearance %.3f m)\n",
					c.name, a, ca, b, cb);
		::testing::Test::RecordProperty(std::string(c.name) + " length ratio", std::to_string(a / b));
		// Both optimise the same grid distance: lengths within a few cells
		// per metre of each other; ours keeps the full radius.
		EXPECT_NEAR(a, b, 0.05 * b) << c.name;
		EXPECT_GE(ca, radius) << c.name;
	}
}

TEST(ValueIterationPlanner, OptionsRoundTripAndBadKeysAreRefused)
{
	ValueIterationPlanner::TOptions changed;
	changed.robotRadius = 0.42;
	changed.obstacleBelow = 0.6;
	changed.maxSweeps = 77;
	changed.tolerance = 1e-4;
	mrpt::config::CConfigFileMemory written;
	changed.saveToConfigFile(written, "ValueIterationPlanner");
	ValueIterationPlanner::TOptions read;
	read.loadFromConfigFile(mrpt::config::CConfigFileMemory(written.getContent()), "ValueIterationPlanner");
	EXPECT_DOUBLE_EQ(read.robotRadius, 0.42);
	EXPECT_DOUBLE_EQ(read.obstacleBelow, 0.6);
	EXPECT_EQ(read.maxSweeps, 77);
	EXPECT_DOUBLE_EQ(read.tolerance, 1e-4);

	auto error = [](const std::string& ini) -> std::string {
		try
		{
			ValueIterationPlanner::TOptions o;
			o.loadFromConfigFile(mrpt::config::CConfigFileMemory(ini), "ValueIterationPlanner");
		}
		catch (const lvf::common::InputError& e)
		{
			return e.what();
		}
		return "";
	};
	EXPECT_NE(error("[ValueIterationPlanner]\nrobot_raduis = 0.3\n").find("robot_raduis: unknown key"), std::string::npos);
	EXPECT_NE(error("[ValueIterationPlanner]\nobstacle_below = 1.5\n").find("obstacle_below"), std::string::npos);
	EXPECT_NE(error("[ValueIterationPlanner]\nmax_sweeps = 0\n").find("max_sweeps"), std::string::npos);
}
