#include <lvfusion/common/InputError.h>
#include <lvfusion/navigation/RandomScenario.h>
#include <lvfusion/navigation/WorldCollision.h>
#include <lvfusion/simulation/RandomWorld.h>

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
	// Step west along the far wall until the robot fits with 0.1 m to spare;
	// a room where it never does keeps its corner and is reported as
	// "target-in-obstacle".
	const WorldCollision collision(s.world, s.world.robot);
	for (mrpt::math::TPoint2D p = s.target; p.x > 0.5; p.x -= 0.25)
		if (collision.clearance(p).distance > 0.1)
		{
			s.target = p;
			break;
		}
	return s;
}

}  // namespace lvf::navigation
