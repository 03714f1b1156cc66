#pragma once

namespace lvf
{
/** DESIGN.md's robot height band: anything with a part at heights in
 * [low, high] above the floor is an obstacle for the robot. */
struct HeightBand
{
	double low = 0.05;	//!< obstacle_min_height [m]
	double high = 1.20;	 //!< robot_height [m]
	bool contains(double z) const { return z >= low && z <= high; }
};
}  // namespace lvf
