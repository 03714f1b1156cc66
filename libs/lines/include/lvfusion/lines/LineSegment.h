#pragma once
// A straight piece of a laser scan: what stage 1 (paper §3) hands to the
// model builder, which raises one vertical plane on each segment.

#include <Eigen/Core>

#include <cstddef>

namespace lvf::lines
{
struct LineSegment
{
	/** Endpoints in the robot frame (x forward, y left) [m], in scan order:
	 * `start` comes from the segment's first ray, `end` from its last. Both
	 * lie on the fitted line (the extreme points projected onto it). */
	Eigen::Vector2d start = Eigen::Vector2d::Zero(), end = Eigen::Vector2d::Zero();
	/** Unit normal of the fitted line, pointing towards the sensor: the side
	 * the laser saw the surface from. */
	Eigen::Vector2d normal = Eigen::Vector2d::UnitX();
	double offset = 0;	//!< the line is normal.dot(p) == offset [m]
	size_t firstIndex = 0, lastIndex = 0;  //!< scan ray indices of its points, inclusive
	size_t pointCount = 0;	//!< valid points fitted (rays in between may be invalid)
	double rmsResidual = 0;	 //!< RMS perpendicular distance of its points to the line [m]
	/** Sphere-of-influence cluster it came from, numbered in scan order:
	 * segments of one cluster are pieces of one connected profile (corners),
	 * segments of different clusters are separated by a gap or a depth jump. */
	size_t cluster = 0;

	double length() const;	//!< |end - start| [m]
	Eigen::Vector2d direction() const;	//!< unit, from start to end
	/** Signed distance of `p` to the line, positive on the sensor's side [m]. */
	double signedDistance(const Eigen::Vector2d& p) const
	{
		return normal.dot(p) - offset;
	}
};

}  // namespace lvf::lines
