#pragma once
// Ground truth from the simulator's exact geometry (DESIGN.md "truth scan",
// "robot height band"): what a perfect 2D sensor would report if it saw
// everything the robot can hit, whatever its height.

#include <lvfusion/simulation/World.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

#include <vector>

namespace lvf::simulation
{
/** For each bearing of `scanGeometry` (its sensorPose, aperture, size), with
 * the robot at `robotPose`: the horizontal range from the sensor origin to the
 * nearest box footprint that has a part in the robot's height band;
 * +infinity where there is none. */
std::vector<float> truthScan(
	const World& world, const mrpt::poses::CPose3D& robotPose,
	const mrpt::obs::CObservation2DRangeScan& scanGeometry);

/** The world's obstacles in the robot band as an occupancy grid: a cell is
 * occupied (0) if any part of it lies inside a band box's footprint, free (1)
 * otherwise. Covers all boxes plus `margin`. */
mrpt::maps::COccupancyGridMap2D obstacleGrid(
	const World& world, double resolution = 0.05, double margin = 0.5);

}  // namespace lvf::simulation
