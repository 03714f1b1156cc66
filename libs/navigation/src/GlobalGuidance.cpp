#include <lvfusion/navigation/GlobalGuidance.h>
#include <lvfusion/planning/PathMetrics.h>
#include <mrpt/core/format.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <iterator>
#include <optional>

namespace lvf::navigation
{
using lvf::planning::GridCell;
using lvf::planning::TraversableGrid;
using mrpt::math::TPoint2D;

namespace
{
/** The traversable cell centre nearest `p` within `radius`, or `p` itself if
 * its cell is traversable; nothing if none is. */
std::optional<TPoint2D> snap(const TraversableGrid& grid, const TPoint2D& p, double radius)
{
	if (!grid.contains(p)) return std::nullopt;
	const GridCell c = grid.cellOf(p);
	if (grid.isTraversable(c)) return p;
	const int reach = int(std::ceil(radius / grid.resolution()));
	const auto& t = grid.traversable();
	std::optional<TPoint2D> best;
	double bestD = radius;
	for (int y = std::max(0, c.y - reach); y <= std::min(t.rows - 1, c.y + reach); y++)
		for (int x = std::max(0, c.x - reach); x <= std::min(t.cols - 1, c.x + reach); x++)
		{
			if (!t(y, x)) continue;
			const TPoint2D q = grid.centreOf({x, y});
			const double d = std::hypot(q.x - p.x, q.y - p.y);
			if (d <= bestD) bestD = d, best = q;
		}
	return best;
}

struct Attempt
{
	lvf::planning::ValueIterationPlanner::Result plan;
	std::string blocked;  //!< non-empty: start or goal could not be snapped
	std::shared_ptr<TraversableGrid> grid;	//!< the grown grid planned on
};

/** The straight segment a-b keeps the robot's centre on traversable cells
 * (sampled every half cell). */
bool straightLineFree(const TraversableGrid& grid, const TPoint2D& a, const TPoint2D& b)
{
	const double len = std::hypot(b.x - a.x, b.y - a.y);
	const int n = std::max(1, int(std::ceil(len / (0.5 * grid.resolution()))));
	for (int i = 0; i <= n; i++)
	{
		const TPoint2D p{a.x + (b.x - a.x) * i / n, a.y + (b.y - a.y) * i / n};
		if (!grid.contains(p) || !grid.isTraversable(grid.cellOf(p))) return false;
	}
	return true;
}

/** The farthest path point within `lookahead` (along the path) that the
 * robot sees in a straight line: a subgoal around a corner would pull a
 * reactive method into the corner. Index into `path`. */
size_t carrotIndex(const std::vector<TPoint2D>& path, const TraversableGrid& grid, double lookahead)
{
	size_t best = std::min<size_t>(1, path.size() - 1);
	double along = 0;
	for (size_t i = 1; i < path.size(); i++)
	{
		along += std::hypot(path[i].x - path[i - 1].x, path[i].y - path[i - 1].y);
		if (along > lookahead) break;
		if (straightLineFree(grid, path.front(), path[i])) best = i;
	}
	return best;
}

Attempt planWithGrowth(
	const mrpt::maps::COccupancyGridMap2D& map, const TPoint2D& robot, const TPoint2D& target,
	const GuidanceOptions& o, double growth)
{
	Attempt a;
	a.grid = std::make_shared<TraversableGrid>(map, growth, o.occupiedBelow);
	const TraversableGrid& grid = *a.grid;
	const auto from = snap(grid, robot, o.snapRadius), to = snap(grid, target, o.snapRadius);
	if (!from) a.blocked = mrpt::format("the robot at (%.2f, %.2f) has no free cell within %.2f m", robot.x, robot.y, o.snapRadius);
	else if (!to) a.blocked = mrpt::format("the target (%.2f, %.2f) has no free cell within %.2f m", target.x, target.y, o.snapRadius);
	// The grid is grown already: the planner's own growth options play no part.
	else a.plan = lvf::planning::ValueIterationPlanner().plan(grid, *from, *to);
	return a;
}

}  // namespace

Guidance planGuidance(
	const LocalObstacleGrid& grid, const TPoint2D& robot, const TPoint2D& target,
	const GuidanceOptions& o)
{
	Guidance g;
	g.subgoal = target;
	const auto seen = grid.obstacleMap();
	std::optional<mrpt::maps::COccupancyGridMap2D> assumed;
	if (o.overhangDepth > 0) grid.assumeOverhangDepth(o.overhangDepth, assumed.emplace(seen));
	if (o.unseenRadius > 0)
		grid.assumeUnseenNear(robot, o.unseenFrom, o.unseenRadius, o.unseenMinHeight, assumed ? *assumed : assumed.emplace(seen));
	const auto* withOverhangs = assumed ? &*assumed : &seen;
	// The full safety growth first, then half of it: the reactive methods
	// slow and dither in gaps that only just fit the robot, so a wider way
	// round is worth some length. Round the overhangs' assumed far parts
	// first; then round what was seen only, ending with the bare radius: a
	// gap only that fits through is still a way.
	const std::pair<const mrpt::maps::COccupancyGridMap2D*, double> attempts[] = {
		{withOverhangs, o.clearance}, {withOverhangs, 0.5 * o.clearance},
		{&seen, o.clearance}, {&seen, 0.5 * o.clearance}, {&seen, 0.0}};
	Attempt a;
	size_t k = 0;
	for (; k < std::size(attempts) && !a.plan.found(); k++)
	{
		const auto [map, clearance] = attempts[k];
		// Without overhang depth or clearance some are the same plan again.
		if (std::find(attempts, attempts + k, attempts[k]) != attempts + k) continue;
		a = planWithGrowth(*map, robot, target, o, o.robotRadius + clearance);
	}
	if (!a.blocked.empty())
	{
		g.detail = a.blocked;
		return g;  // Direct
	}
	if (!a.plan.found())
	{
		g.status = Guidance::Status::Unreachable;
		g.detail = lvf::planning::describe(a.plan.outcome) + " on the robot's obstacle grid";
		return g;
	}
	g.status = Guidance::Status::Path;
	g.keepsOffAssumed = attempts[k - 1].first == withOverhangs && assumed;
	g.clearance = attempts[k - 1].second;
	g.path = std::move(a.plan.path);
	g.pathLength = lvf::planning::pathLength(g.path);
	const size_t carrot = carrotIndex(g.path, *a.grid, o.lookahead);
	g.subgoalIsTarget = carrot + 1 == g.path.size();
	g.subgoal = g.subgoalIsTarget ? target : g.path[carrot];
	return g;
}

}  // namespace lvf::navigation
