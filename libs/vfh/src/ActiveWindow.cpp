#include <lvfusion/vfh/ActiveWindow.h>

#include <algorithm>

namespace lvf::vfh
{
double certaintyFromOccupancy(double occupancy)
{
	return std::clamp(2.0 * occupancy - 1.0, 0.0, 1.0);
}

std::vector<ObstacleCell> activeWindow(
	const mrpt::maps::COccupancyGridMap2D& grid, const mrpt::math::TPoint2D& robot, double radius)
{
	std::vector<ObstacleCell> cells;
	const int cx0 = std::max(0, grid.x2idx(robot.x - radius));
	const int cx1 = std::min(int(grid.getSizeX()) - 1, grid.x2idx(robot.x + radius));
	const int cy0 = std::max(0, grid.y2idx(robot.y - radius));
	const int cy1 = std::min(int(grid.getSizeY()) - 1, grid.y2idx(robot.y + radius));
	const double r2 = radius * radius;
	for (int cy = cy0; cy <= cy1; cy++)
		for (int cx = cx0; cx <= cx1; cx++)
		{
			const double dx = grid.idx2x(cx) - robot.x, dy = grid.idx2y(cy) - robot.y;
			if (dx * dx + dy * dy > r2) continue;
			// MRPT grids store the probability of being free (0 = occupied).
			const double c = certaintyFromOccupancy(1.0 - grid.getCell(cx, cy));
			if (c > 0) cells.push_back({dx, dy, c});
		}
	return cells;
}

std::vector<ObstacleCell> activeWindow(const std::vector<mrpt::math::TPoint2D>& points, double radius)
{
	std::vector<ObstacleCell> cells;
	for (const auto& p : points)
		if (p.x * p.x + p.y * p.y <= radius * radius) cells.push_back({p.x, p.y, 1.0});
	return cells;
}

}  // namespace lvf::vfh
