#pragma once
// Putting scans into MRPT's occupancy grids without letting a pose make them
// unbounded. MRPT's grids grow to take in whatever is inserted and never
// shrink: a run whose odometry starts far from the origin gets a grid
// reaching back to it, and one corrupt pose (1e180 m, found by
// fuzz_fusion_frame) makes MRPT's resize assert and abort the program.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <initializer_list>
#include <utility>

namespace lvf::common
{
/** Empties `grid` to 2 m x 2 m round (x, y), at its own resolution. A new or
 * cleared MRPT grid spans 20 m round the origin; the Freiburg logs'
 * odometry starts hundreds of metres out (mit-csail at x = 577 m). Grids
 * started where the run starts cover where it went and no more. A point
 * that is not finite leaves the grid as it is. */
void startGridAround(mrpt::maps::COccupancyGridMap2D& grid, double x, double y);

/** How far past its current extent one scan may make a grid grow [m]. */
constexpr double kMaxGridGrowth = 1000.0;

/** Whether `scan`, taken with the robot at `robot`, can go into `grid`: its
 * sensor's pose finite and within kMaxGridGrowth (plus the scan's range)
 * of the grid's extent. */
bool insertableInGrid(
	const mrpt::maps::COccupancyGridMap2D& grid, const mrpt::poses::CPose3D& robot,
	const mrpt::obs::CObservation2DRangeScan& scan);

/** A grid and the scan it takes at one pose (null: none this time). */
using GridAndScan = std::pair<mrpt::maps::COccupancyGridMap2D*, const mrpt::obs::CObservation2DRangeScan*>;

/** One robot pose's scans into their grids, all or none: with `first` (no
 * scan inserted yet) every grid is started round the pose, then each scan
 * goes into its grid if every scan can (insertableInGrid). False, and
 * nothing inserted, otherwise. */
bool insertScansAt(const mrpt::poses::CPose2D& pose, bool first, std::initializer_list<GridAndScan> gridsAndScans);

}  // namespace lvf::common
