#pragma once
// How well an occupancy grid built from scans shows the obstacles of the
// robot's height band, against the simulator's ground-truth obstacle grid
// (NAME_obstacles.gridmap.gz).
//
// Only what the map has observed is judged: a map cannot know a cell it never
// saw, and a scan-built map sees the faces of obstacles, not their insides.
//   recall    = truth obstacle cells the map observed that it marks occupied
//               (within `tolerance` of an occupied map cell) / truth obstacle
//               cells the map observed;
//   precision = map occupied cells within `tolerance` of a truth obstacle
//               cell / map occupied cells.
// A cell is occupied when MRPT's value (probability of being free) is below
// 0.5 - margin, free above 0.5 + margin, unobserved in between. The map's
// frame lies at `mapInTruth` in the truth's (a map built in a run's odometry
// frame need not share the simulator's world frame).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose2D.h>

namespace lvf::metrics
{
struct ObstacleGridScore
{
	size_t truthObserved = 0, truthFound = 0;
	size_t mapOccupied = 0, mapCorrect = 0;
	double recall() const { return truthObserved ? double(truthFound) / double(truthObserved) : NAN; }
	double precision() const { return mapOccupied ? double(mapCorrect) / double(mapOccupied) : NAN; }
};

ObstacleGridScore scoreObstacleGrid(
	const mrpt::maps::COccupancyGridMap2D& map, const mrpt::maps::COccupancyGridMap2D& truth,
	const mrpt::poses::CPose2D& mapInTruth = {}, double tolerance = 0.10, double margin = 0.05);

}  // namespace lvf::metrics
