#pragma once
// Where a round robot's centre may be, on an occupancy grid: the obstacles
// grown by the robot's radius (paper §7 plans for the robot's centre).
//
// MRPT's COccupancyGridMap2D stores per cell the probability that it is FREE
// (1 = free, 0 = occupied, 0.5 = never observed). A cell is an obstacle when
// that value is below `obstacleBelow`: with 0.5, a cell more likely occupied
// than free. Unobserved cells (0.5) are then traversable; a threshold above
// 0.5 makes them obstacles too.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>
#include <opencv2/core.hpp>

namespace lvf::planning
{
struct GridCell
{
	int x = 0, y = 0;  //!< column, row (MRPT's cx, cy)
	bool operator==(const GridCell& o) const { return x == o.x && y == o.y; }
};

class TraversableGrid
{
   public:
	/** @param robotRadius [m] @param obstacleBelow see above */
	TraversableGrid(const mrpt::maps::COccupancyGridMap2D& grid, double robotRadius, double obstacleBelow);

	/** 1 where the robot's centre may be, 0 where its disc would overlap an
	 * obstacle cell; rows = MRPT's cy, columns = cx. */
	const cv::Mat1b& traversable() const { return m_traversable; }
	/** Per cell, the distance from its centre to the nearest obstacle cell's
	 * centre [m] (0 on obstacles, +inf on a grid without any). */
	const cv::Mat1f& clearance() const { return m_clearance; }

	bool contains(const mrpt::math::TPoint2D& p) const;
	GridCell cellOf(const mrpt::math::TPoint2D& p) const;
	mrpt::math::TPoint2D centreOf(const GridCell& c) const;
	bool isTraversable(const GridCell& c) const { return m_traversable(c.y, c.x) != 0; }
	bool isObstacle(const GridCell& c) const { return m_clearance(c.y, c.x) == 0; }
	double resolution() const { return m_resolution; }
	/** Clearance [m] at a metric point (0 outside the grid). */
	double clearanceAt(const mrpt::math::TPoint2D& p) const;

   private:
	double m_xMin, m_yMin, m_resolution;
	cv::Mat1b m_traversable;
	cv::Mat1f m_clearance;
};

}  // namespace lvf::planning
