#pragma once
// Where the cameras have seen through the robot's height band: a 3D
// occupancy grid (MRPT's COccupancyGridMap3D) of the band over the robot's
// area, carved by the rays of the pixels whose depth is known -- those the
// scene model explains (the ray reaches the floor or a wall the laser saw)
// and those the focused search matched. A pixel neither explains (searched,
// no match) carves nothing: something is somewhere along its ray; nor does
// an untextured one (SeenRays.h).
//
// The 2D grids cannot tell this: a ray that passes *under* a floating box
// and reaches the floor behind it clears the box's cells in a 2D grid,
// while here it clears only the voxels below the box. A column is "seen
// free" when the voxels of the band above it have been seen free. The plan
// keeps off columns near the robot that are not, and the robot turns to
// look at them before it goes through (GuidanceOptions::unseenRadius), so it
// moves where the cameras have looked through the band -- the sides of a
// floating box it saw only from the front included.

#include <lvfusion/common/HeightBand.h>
#include <mrpt/maps/COccupancyGridMap3D.h>
#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPoint3D.h>

#include <cmath>

namespace lvf::navigation
{
class SeenSpace
{
   public:
	/** Covers [xMin, xMax] x [yMin, yMax] (world frame) and the band's
	 * heights, in voxels of `resolution` [m]. */
	SeenSpace(double xMin, double xMax, double yMin, double yMax, const lvf::HeightBand& band, double resolution);

	/** A ray from `from` that reached `to` (world frame): the voxels it
	 * crosses are free, the one at `to` occupied -- an obstacle, a wall, or
	 * the floor (below the band, where it is not counted). */
	void insertRay(const mrpt::math::TPoint3D& from, const mrpt::math::TPoint3D& to);
	/** The whole band over a disk is free: the robot's body stands there
	 * (it is as tall as the band). */
	void markFree(const mrpt::math::TPoint2D& centre, double radius);

	/** How much of the band over (x, y) has not been seen free (unseen or
	 * occupied voxels) [m]; 0: the whole column is seen free. */
	double unseenHeight(double x, double y) const;

   private:
	int index(double coordinate, double origin) const { return int(std::floor((coordinate - origin) / m_resolution)); }
	double middle(int index, double origin) const { return origin + (index + 0.5) * m_resolution; }

	mrpt::maps::COccupancyGridMap3D m_voxels;
	lvf::HeightBand m_band;
	double m_resolution, m_xMin, m_yMin;
	int m_bandVoxels;  //!< voxels from the band's lower edge up (the last may reach past its top)
};

}  // namespace lvf::navigation
