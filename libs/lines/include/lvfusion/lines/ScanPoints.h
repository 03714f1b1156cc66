#pragma once
// The valid returns of a 2D scan as points in the robot frame, in scan order:
// the input of line extraction.

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <Eigen/Core>
#include <vector>

namespace lvf::lines
{
struct ScanPoints
{
	std::vector<Eigen::Vector2d> xy;  //!< robot frame (x forward, y left) [m]
	std::vector<size_t> ray;  //!< the scan index each point came from
	Eigen::Vector2d origin = Eigen::Vector2d::Zero();  //!< the sensor, robot frame [m]

	size_t size() const { return xy.size(); }
};

/** Points of the rays that are valid (getScanRangeValidity) and whose range
 * is finite, > 0 and < maxRange (drivers disagree on how they flag "no
 * return"; a range at maxRange is never a surface). Bearing i is
 * scan.getScanAngle(i); the sensor pose is taken as level (x, y, yaw of
 * scan.sensorPose), as for every 2D laser the method assumes. */
ScanPoints scanPoints(const mrpt::obs::CObservation2DRangeScan& scan);

}  // namespace lvf::lines
