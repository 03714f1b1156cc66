#pragma once
// Figures of a planned path, for comparing planners and maps.

#include <lvfusion/planning/TraversableGrid.h>

#include <vector>

namespace lvf::planning
{
using Path = std::vector<mrpt::math::TPoint2D>;

/** Sum of the segment lengths [m]. */
double pathLength(const Path& path);

/** Smallest distance from the path (sampled every quarter cell along each
 * segment) to the centre of an obstacle cell of `grid` [m]; 0 where the path
 * runs through an obstacle cell or leaves the grid. */
double minimumClearance(const Path& path, const TraversableGrid& grid);

/** Length of the path [m] that lies inside obstacle cells of `grid` (sampled
 * every quarter cell): > 0 means the path runs through an obstacle. */
double lengthThroughObstacles(const Path& path, const TraversableGrid& grid);

}  // namespace lvf::planning
