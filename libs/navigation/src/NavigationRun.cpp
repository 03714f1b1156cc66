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
constexpr double kMaxDistanceOutsideWorld = 1000;	// [m]

/** Checks a scenario can be run at all; fills `m` and returns false if not. */
bool checkScenario(const NavigationScenario& s, const WorldCollision& collision, NavigationMetrics& m)
{
	if (!finite(s.start) || !std::isfinite(s.target.x) || !std::isfinite(s.target.y))
	{
		m.outcome = Outcome::InvalidPose;
		m.detail = "start " + s.start.asString() + " or target " + s.target.asString() + " is not finite";
		return false;
	}
	// The robot's grids cover the world, the start and the target (gridFor):
	// a point far off would ask for more cells than memory holds.
	double xMin, xMax, yMin, yMax;
	s.world.footprintBounds(xMin, xMax, yMin, yMax, kMaxDistanceOutsideWorld);
	for (const auto& [what, p] : {std::pair{"start", mrpt::math::TPoint2D(s.start)}, std::pair{"target", s.target}})
		if (p.x < xMin || p.x > xMax || p.y < yMin || p.y > yMax)
		{
			m.outcome = Outcome::InvalidPose;
			m.detail = mrpt::format("the %s (%g, %g) lies more than %.0f m outside the world", what, p.x, p.y,
				kMaxDistanceOutsideWorld);
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

/** The robot's grids, covering the world and the scenario's start and
 * target with a metre to spare: a target beyond the world's walls is still
 * a cell the planner can find closed off. */
std::unique_ptr<LocalObstacleGrid> gridFor(const NavigationScenario& scenario, const NavigationLoopOptions& loop)
{
	double xMin, xMax, yMin, yMax;
	scenario.world.footprintBounds(xMin, xMax, yMin, yMax, 1.0);
	for (const auto& p : {mrpt::math::TPoint2D(scenario.start), scenario.target})
	{
		xMin = std::min(xMin, p.x - 1.0), xMax = std::max(xMax, p.x + 1.0);
		yMin = std::min(yMin, p.y - 1.0), yMax = std::max(yMax, p.y + 1.0);
	}
	return std::make_unique<LocalObstacleGrid>(xMin, xMax, yMin, yMax, loop.gridResolution, loop.occupiedBelow, loop.visionObstacleMargin);
}

}  // namespace

NavigationRun runNavigation(const NavigationScenario& scenario, const NavigationSetup& setup)
{
	NavigationRun run;
	const WorldCollision collision(scenario.world, scenario.world.robot);
	if (!checkScenario(scenario, collision, run.metrics)) return run;
	run.grid = gridFor(scenario, setup.loop);
	ClosedLoop(scenario, setup, collision, run).run();
	return run;
}

}  // namespace lvf::navigation
