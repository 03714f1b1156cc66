#pragma once
// Seeded random indoor worlds for tests, benchmarks and batch runs: a
// rectangular room with obstacles the laser sees (boxes on the floor) and
// obstacles it does not (floating boxes, table tops, wall shelves), some
// walls textureless (obstacles are always textured: a textureless obstacle is
// invisible to any stereo method, and the tests score what vision can see). The robot starts at the middle of the south wall
// looking north; nothing is placed within `clearRadius` of its start.

#include <lvfusion/simulation/World.h>

namespace lvf::simulation
{
struct RandomWorldOptions
{
	double roomMin = 6.0, roomMax = 8.0;  //!< room side range [m]
	int floorBoxes = 3;	 //!< laser-visible boxes
	int floatingBoxes = 3;	//!< boxes above the laser plane, inside the band
	int tables = 1;
	int wallShelves = 1;  //!< shelves hung above the laser plane
	double texturelessFraction = 0.3;  //!< walls with texture "none"
	double clearRadius = 1.2;  //!< free space around the start [m]
	int pathPoses = 2;	//!< poses, 0.2 m apart, driving north
};

World generateRandomWorld(uint32_t seed, const RandomWorldOptions& options = RandomWorldOptions());

}  // namespace lvf::simulation
