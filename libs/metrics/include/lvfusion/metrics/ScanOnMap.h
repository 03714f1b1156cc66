#pragma once
// Whether a localised scan lies on the map it was localised in: the share of
// its returns that fall within one cell of a cell the map holds more likely
// occupied than free. It needs no ground truth, so it tells on real logs
// whether a particle filter still follows the robot: at the exact start of
// the Freiburg mit-csail log a scan scores 0.43 (glass, clutter, rays past
// what the map holds), a followed robot 0.35-1.0 scan by scan, a lost one
// about 0.1 (share/doc/lvfusion/measurements.md, lvf-map).

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

namespace lvf::metrics
{
/** The share of `scan`'s valid returns within `maxRange` (every `rayStep`-th
 * ray) that, from the robot at `robot`, land within a cell of an occupied
 * cell of `map`; 1 if it has none. */
double scanShareOnMap(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot,
	const mrpt::maps::COccupancyGridMap2D& map, double maxRange, size_t rayStep = 2);

}  // namespace lvf::metrics
