#pragma once
// Obstacle courses for the navigation tests: boxes painted into an MRPT
// occupancy grid, a start at the origin and a target.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

namespace lvf::test
{
struct Box
{
	mrpt::math::TPoint2D min, max;
	/** Distance from a point to the box, 0 inside [m]. */
	double distance(const mrpt::math::TPoint2D& p) const
	{
		const double dx = std::max({min.x - p.x, 0.0, p.x - max.x});
		const double dy = std::max({min.y - p.y, 0.0, p.y - max.y});
		return std::hypot(dx, dy);
	}
};

struct Course
{
	std::string name;
	mrpt::math::TPoint2D target;
	std::vector<Box> obstacles;
};
inline void PrintTo(const Course& c, std::ostream* os) { *os << c.name; }

/** Marks the cells of every box occupied (as MRPT's rnav_unittest does:
 * indices from x2idx(min) up to, not including, x2idx(max)); the rest of
 * the grid free. MRPT grids hold p(free): 0.9 free, 0 occupied. Returns
 * the boxes as painted (whole cells): the obstacles the robot must avoid. */
inline std::vector<Box> paintCourse(mrpt::maps::COccupancyGridMap2D& grid, const Course& c)
{
	grid.fill(0.9f);
	std::vector<Box> painted;
	const double half = 0.5 * grid.getResolution();
	for (const auto& b : c.obstacles)
	{
		const int cx0 = grid.x2idx(b.min.x), cx1 = grid.x2idx(b.max.x);
		const int cy0 = grid.y2idx(b.min.y), cy1 = grid.y2idx(b.max.y);
		for (int cx = cx0; cx < cx1; cx++)
			for (int cy = cy0; cy < cy1; cy++) grid.setCell(cx, cy, 0.0f);
		painted.push_back(
			{{grid.idx2x(cx0) - half, grid.idx2y(cy0) - half},
			 {grid.idx2x(cx1 - 1) + half, grid.idx2y(cy1 - 1) + half}});
	}
	return painted;
}

}  // namespace lvf::test
