#include <lvfusion/common/IniSection.h>
#include <lvfusion/planning/ValueFunction.h>
#include <lvfusion/planning/ValueIterationPlanner.h>

#include <cmath>
#include <limits>

namespace lvf::planning
{
using lvf::common::writeOption;

void ValueIterationPlanner::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	robotRadius = ini.real("robot_radius", robotRadius, 0, 10);
	obstacleBelow = ini.real("obstacle_below", obstacleBelow, 0, 1);
	maxSweeps = ini.integer("max_sweeps", maxSweeps, 1);
	tolerance = ini.real("tolerance", tolerance, 0, 1);
	ini.rejectUnknownKeys();
}

void ValueIterationPlanner::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "robot_radius", robotRadius, "obstacles are grown by this [m]");
	writeOption(c, s, "obstacle_below", obstacleBelow, "cells less likely free than this are obstacles (0.5: unobserved cells are not) [probability]");
	writeOption(c, s, "max_sweeps", maxSweeps, "safety bound on value-iteration sweeps [count]");
	writeOption(c, s, "tolerance", tolerance, "converged when no cost-to-go changes by more [m]");
}

std::string describe(PlanOutcome outcome)
{
	switch (outcome)
	{
		case PlanOutcome::Found: return "path found";
		case PlanOutcome::Unreachable: return "no collision-free path joins start and goal";
		case PlanOutcome::SweepsExhausted:
			return "value iteration stopped at its sweep bound (max_sweeps) before it converged: no path yet";
		case PlanOutcome::StartOutsideMap: return "the start is outside the map";
		case PlanOutcome::GoalOutsideMap: return "the goal is outside the map";
		case PlanOutcome::StartBlocked: return "the start is inside an obstacle (grown by the robot radius)";
		case PlanOutcome::GoalBlocked: return "the goal is inside an obstacle (grown by the robot radius)";
	}
	return "?";
}

ValueIterationPlanner::Result ValueIterationPlanner::plan(
	const mrpt::maps::COccupancyGridMap2D& map, const mrpt::math::TPoint2D& start,
	const mrpt::math::TPoint2D& goal) const
{
	return plan(TraversableGrid(map, m_options.robotRadius, m_options.obstacleBelow), start, goal);
}

ValueIterationPlanner::Result ValueIterationPlanner::plan(
	const TraversableGrid& grid, const mrpt::math::TPoint2D& start,
	const mrpt::math::TPoint2D& goal) const
{
	Result r;
	if (!grid.contains(start)) r.outcome = PlanOutcome::StartOutsideMap;
	else if (!grid.contains(goal)) r.outcome = PlanOutcome::GoalOutsideMap;
	else if (!grid.isTraversable(grid.cellOf(start))) r.outcome = PlanOutcome::StartBlocked;
	else if (!grid.isTraversable(grid.cellOf(goal))) r.outcome = PlanOutcome::GoalBlocked;
	if (r.outcome != PlanOutcome::Unreachable) return r;

	const GridCell from = grid.cellOf(start), to = grid.cellOf(goal);
	const ValueFunction vf = computeValueFunction(
		grid, to, static_cast<size_t>(m_options.maxSweeps), m_options.tolerance);
	r.sweeps = vf.sweeps;
	r.converged = vf.converged;
	const cv::Mat1f& v = vf.value;
	// Unreachable, unless the sweeps stopped before the values settled.
	r.outcome = vf.converged ? PlanOutcome::Unreachable : PlanOutcome::SweepsExhausted;
	if (!std::isfinite(v(from.y, from.x))) return r;
	r.costToGo = v(from.y, from.x);

	// Descend: the move minimising cost + V; at the fixed point that sum
	// equals V(here), and V(next) < V(here), so the walk cannot loop.
	const auto moves = gridMoves(static_cast<float>(grid.resolution()));
	const auto isFree = [&](int x, int y) {
		return x >= 0 && y >= 0 && x < v.cols && y < v.rows && grid.isTraversable({x, y});
	};
	r.path.push_back(start);
	GridCell here = from;
	for (size_t steps = 0; !(here == to) && steps < v.total(); steps++)
	{
		GridCell best = here;
		float bestValue = std::numeric_limits<float>::infinity();
		for (const GridMove& m : moves)
		{
			if (!moveAllowed(isFree, here.x, here.y, m)) continue;
			const GridCell n{here.x + m.dx, here.y + m.dy};
			const float q = m.cost + v(n.y, n.x);
			if (q < bestValue) bestValue = q, best = n;
		}
		if (!(v(best.y, best.x) < v(here.y, here.x))) break;  // not converged (max_sweeps hit)
		here = best;
		if (!(here == to)) r.path.push_back(grid.centreOf(here));
	}
	if (!(here == to))
	{
		r.path.clear();	 // no half path beside an outcome that is no path
		return r;
	}
	r.path.push_back(goal);
	r.outcome = PlanOutcome::Found;
	return r;
}

}  // namespace lvf::planning
