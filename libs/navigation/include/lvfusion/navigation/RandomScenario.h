#pragma once
// Seeded random navigation scenarios for batch runs: a random room
// (lvf::simulation::generateRandomWorld) with the robot at its start and a
// target in the far corner, moved along the far wall until the robot can
// stand there.

#include <lvfusion/navigation/NavigationRun.h>

namespace lvf::navigation
{
enum class RoomKind
{
	Overhangs,	//!< tables, shelves and floating boxes the laser cannot see
	LaserVisible  //!< only boxes standing on the floor
};
const char* roomKindName(RoomKind k);
/** "overhangs" / "visible"; throws InputError naming `source` otherwise. */
RoomKind parseRoomKind(const std::string& name, const std::string& source);

NavigationScenario randomScenario(uint32_t seed, RoomKind kind);

}  // namespace lvf::navigation
