#include <lvfusion/common/InputError.h>
#include <lvfusion/navigation/RandomScenario.h>
#include <lvfusion/navigation/WorldCollision.h>
#include <lvfusion/planning/ValueIterationPlanner.h>
#include <lvfusion/simulation/GroundTruth.h>
#include <lvfusion/simulation/RandomWorld.h>

#include <optional>

namespace lvf::navigation
{
const char* roomKindName(RoomKind k) { return k == RoomKind::Overhangs ? "overhangs" : "visible"; }

RoomKind parseRoomKind(const std::string& name, const std::string& source)
{
	if (name == "overhangs") return RoomKind::Overhangs;
	if (name == "visible") return RoomKind::LaserVisible;
	throw lvf::common::InputError(source, "", "'" + name + "' is not a room kind (overhangs, visible)");
}

NavigationScenario randomScenario(uint32_t seed, RoomKind kind)
{
	lvf::simulation::RandomWorldOptions o;
	if (kind == RoomKind::Overhangs)
	{
		o.floorBoxes = 3;
		o.floatingBoxes = 3;
		o.tables = 2;
		o.wallShelves = 2;
	}
	else
	{
		o.floorBoxes = 6;
		o.floatingBoxes = o.tables = o.wallShelves = 0;
	}
	NavigationScenario s;
	s.world = lvf::simulation::generateRandomWorld(seed, o);
	s.world.name = std::string(roomKindName(kind)) + "_" + std::to_string(seed);
	s.start = s.world.path.front();
	s.target = *s.world.target;
	// Step west along the far wall until the robot fits with 0.1 m to spare
	// and a way leads there: random clutter can wall a corner in (seeds 17,
	// 34 and 50 of the overhang rooms did), and a batch measures obstacle
	// avoidance, not tasks no robot could do. The way is planned on the
	// world's true obstacles in the robot's band, grown by its radius. A
	// room where the robot fits nowhere keeps its corner and is reported as
	// "target-in-obstacle"; one where it fits but no way leads there keeps
	// the first place it fits, and the run reports it "unreachable".
	const WorldCollision collision(s.world, s.world.robot);
	const auto obstacles = lvf::simulation::obstacleGrid(s.world, 0.05, 0.5);
	lvf::planning::ValueIterationPlanner::TOptions planner;
	planner.robotRadius = s.world.robot.radius;
	const lvf::planning::ValueIterationPlanner plan(planner);
	const mrpt::math::TPoint2D from{s.start.x, s.start.y};
	std::optional<mrpt::math::TPoint2D> fits;
	for (mrpt::math::TPoint2D p = s.target; p.x > 0.5; p.x -= 0.25)
	{
		if (collision.clearance(p).distance <= 0.1) continue;
		if (!fits) fits = p;
		if (plan.plan(obstacles, from, p).found())
		{
			fits = p;
			break;
		}
	}
	if (fits) s.target = *fits;
	return s;
}

}  // namespace lvf::navigation
