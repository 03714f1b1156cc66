#pragma once
// A test on the cells of an occupancy grid round a point, shared by the
// metrics that ask whether a map has something near where it should.

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <cmath>

namespace lvf::metrics
{
/** Whether any cell within `radius` [m] of (x, y) (cell centres, from the
 * cell (x, y) falls in) satisfies `test` on its free probability. */
template <typename Test>
bool anyCellNear(const mrpt::maps::COccupancyGridMap2D& g, double x, double y, double radius, Test test)
{
	const int cx = g.x2idx(x), cy = g.y2idx(y);
	const int r = static_cast<int>(std::ceil(radius / g.getResolution()));
	for (int dy = -r; dy <= r; dy++)
		for (int dx = -r; dx <= r; dx++)
		{
			const int nx = cx + dx, ny = cy + dy;
			if (nx < 0 || ny < 0 || nx >= int(g.getSizeX()) || ny >= int(g.getSizeY())) continue;
			if (std::hypot(dx, dy) * g.getResolution() > radius + 1e-9) continue;
			if (test(g.getCell(nx, ny))) return true;
		}
	return false;
}

}  // namespace lvf::metrics
