#include "ClosedLoop.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/navigation/NavigationRun.h>
#include <lvfusion/navigation/WorldCollision.h>

#include <algorithm>
#include <cmath>

namespace lvf::navigation
{
const char* sensingName(Sensing s) { return s == Sensing::Fused ? "fused" : "laser"; }

Sensing parseSensing(const std::string& name, const std::string& source)
{
	if (name == "fused") return Sensing::Fused;
	if (name == "laser") return Sensing::Laser;
	throw lvf::common::InputError(source, "", "'" + name + "' is not a sensing mode (fused, laser)");
}

namespace
{
/** The most cells the robot's grids may hold. Each guidance step plans on
 * the whole grid: at 23 million cells (the box room with a target at
 * (240, 240), 5 cm cells) a control step took 0.18 s and the run 0.6 GB; a
 * target at (900, 900), 3e8 cells, 3.7 s a step and 6 GB. */
constexpr double kMaxGridCells = 25e6;

struct Bounds
{
	double xMin, xMax, yMin, yMax;
	double cells(double resolution) const { return (xMax - xMin) * (yMax - yMin) / (resolution * resolution); }
};

/** What the robot's grids cover: the world, the start and the target with a
 * metre to spare (a target beyond the world's walls is still a cell the
 * planner can find closed off). */
Bounds gridBounds(const NavigationScenario& scenario)
{
	Bounds b;
	scenario.world.footprintBounds(b.xMin, b.xMax, b.yMin, b.yMax, 1.0);
	for (const auto& p : {mrpt::math::TPoint2D(scenario.start), scenario.target})
	{
		b.xMin = std::min(b.xMin, p.x - 1.0), b.xMax = std::max(b.xMax, p.x + 1.0);
		b.yMin = std::min(b.yMin, p.y - 1.0), b.yMax = std::max(b.yMax, p.y + 1.0);
	}
	return b;
}

/** Checks a scenario can be run at all; fills `m` and returns false if not. */
bool checkScenario(
	const NavigationScenario& s, const WorldCollision& collision, double gridResolution, NavigationMetrics& m)
{
	if (!finite(s.start) || !std::isfinite(s.target.x) || !std::isfinite(s.target.y))
	{
		m.outcome = Outcome::InvalidPose;
		m.detail = "start " + s.start.asString() + " or target " + s.target.asString() + " is not finite";
		return false;
	}
	// A start or target far off would ask for more cells than a run can plan on.
	if (const double cells = gridBounds(s).cells(gridResolution); cells > kMaxGridCells)
	{
		m.outcome = Outcome::InvalidPose;
		m.detail = mrpt::format(
			"the start %s and the target (%g, %g) lie so far apart, or so far from the world, that the robot's grids "
			"would need %.3g cells at grid_resolution %g m (at most %.3g)",
			s.start.asString().c_str(), s.target.x, s.target.y, cells, gridResolution, kMaxGridCells);
		return false;
	}
	if (const auto c = collision.clearance(mrpt::math::TPoint2D(s.start)); c.distance < 0)
	{
		m.outcome = Outcome::StartInCollision;
		m.minClearance = c.distance;
		m.detail = mrpt::format("the robot starts %.3f m into '%s'", -c.distance, collision.boxName(c.box).c_str());
		return false;
	}
	if (const auto c = collision.clearance(s.target); c.distance < 0)
	{
		m.outcome = Outcome::TargetInObstacle;
		m.detail = mrpt::format("the robot cannot stand at the target: %.3f m into '%s'", -c.distance, collision.boxName(c.box).c_str());
		return false;
	}
	return true;
}

std::unique_ptr<LocalObstacleGrid> gridFor(const NavigationScenario& scenario, const NavigationLoopOptions& loop)
{
	const Bounds b = gridBounds(scenario);
	return std::make_unique<LocalObstacleGrid>(
		b.xMin, b.xMax, b.yMin, b.yMax, loop.gridResolution, loop.occupiedBelow, loop.visionObstacleMargin);
}

}  // namespace

NavigationRun runNavigation(const NavigationScenario& scenario, const NavigationSetup& setup)
{
	NavigationRun run;
	const WorldCollision collision(scenario.world, scenario.world.robot);
	if (!checkScenario(scenario, collision, setup.loop.gridResolution, run.metrics)) return run;
	run.grid = gridFor(scenario, setup.loop);
	ClosedLoop(scenario, setup, collision, run).run();
	return run;
}

}  // namespace lvf::navigation
