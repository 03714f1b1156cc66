#include <lvfusion/planning/TraversableGrid.h>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <limits>

namespace lvf::planning
{
TraversableGrid::TraversableGrid(
	const mrpt::maps::COccupancyGridMap2D& grid, double robotRadius, double obstacleBelow)
	: m_xMin(grid.getXMin()), m_yMin(grid.getYMin()), m_resolution(grid.getResolution())
{
	const int cols = static_cast<int>(grid.getSizeX()), rows = static_cast<int>(grid.getSizeY());
	cv::Mat1b free(rows, cols);
	for (int y = 0; y < rows; y++)
		for (int x = 0; x < cols; x++)
			free(y, x) = grid.getCell(x, y) >= obstacleBelow ? 255 : 0;
	// OpenCV's exact Euclidean distance transform: distance of every free
	// cell's centre to the nearest obstacle cell's centre, in cells.
	cv::distanceTransform(free, m_clearance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
	m_clearance *= m_resolution;
	if (static_cast<size_t>(cv::countNonZero(free)) == free.total())	 // no obstacle at all: clear everywhere
		m_clearance.setTo(std::numeric_limits<float>::infinity());
	// An obstacle cell reaches half a cell towards its neighbours: the disc
	// is clear of it when the centres are at least radius + res/2 apart.
	const float blocked = static_cast<float>(robotRadius + 0.5 * m_resolution);
	m_traversable = m_clearance >= blocked;
	m_traversable /= 255;
}

bool TraversableGrid::contains(const mrpt::math::TPoint2D& p) const
{
	const GridCell c = cellOf(p);
	return c.x >= 0 && c.y >= 0 && c.x < m_traversable.cols && c.y < m_traversable.rows;
}

GridCell TraversableGrid::cellOf(const mrpt::math::TPoint2D& p) const
{
	return {static_cast<int>(std::floor((p.x - m_xMin) / m_resolution)),
			static_cast<int>(std::floor((p.y - m_yMin) / m_resolution))};
}

mrpt::math::TPoint2D TraversableGrid::centreOf(const GridCell& c) const
{
	return {m_xMin + (c.x + 0.5) * m_resolution, m_yMin + (c.y + 0.5) * m_resolution};
}

double TraversableGrid::clearanceAt(const mrpt::math::TPoint2D& p) const
{
	if (!contains(p)) return 0;
	const GridCell c = cellOf(p);
	return m_clearance(c.y, c.x);
}

}  // namespace lvf::planning
