#pragma once
// VFH's active window: the obstacle cells around the robot that the polar
// histogram is built from, as offsets from the robot's centre with a
// certainty value. The offsets keep the axes of their source (a grid's world
// axes, or the robot's own), and the histogram's sectors are angles in that
// frame, so a world-aligned window goes with a heading = robot yaw and a
// robot-frame one with heading 0.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>

#include <vector>

namespace lvf::vfh
{
struct ObstacleCell
{
	double dx = 0, dy = 0;	//!< offset from the robot's centre [length]
	double certainty = 1;	//!< VFH's c_ij, here in [0, 1]
};

/** Certainty of an obstacle from an occupancy probability: VFH counts
 * evidence of an obstacle, so free and unknown (p <= 0.5) count nothing and
 * certainty rises linearly to 1 at p = 1. Without this every unexplored cell
 * of an MRPT grid (p = 0.5) would be half an obstacle. */
double certaintyFromOccupancy(double occupancy);

/** The cells of `grid` whose centres lie within `radius` of `robot` and
 * carry some certainty, as world-aligned offsets [m]. */
std::vector<ObstacleCell> activeWindow(
	const mrpt::maps::COccupancyGridMap2D& grid, const mrpt::math::TPoint2D& robot, double radius);

/** Obstacle points (e.g. a scan's returns in the robot frame), each a fully
 * certain cell, those within `radius` of the origin. */
std::vector<ObstacleCell> activeWindow(const std::vector<mrpt::math::TPoint2D>& points, double radius);

}  // namespace lvf::vfh
