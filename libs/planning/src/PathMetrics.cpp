#include <lvfusion/planning/PathMetrics.h>

#include <algorithm>
#include <cmath>
#include <functional>

namespace lvf::planning
{
namespace
{
/** Calls visit(point, length it stands for) at quarter-cell steps along the path. */
void samplePath(
	const Path& path, double step,
	const std::function<void(const mrpt::math::TPoint2D&, double)>& visit)
{
	for (size_t i = 0; i + 1 < path.size(); i++)
	{
		const auto& a = path[i];
		const auto& b = path[i + 1];
		const double len = std::hypot(b.x - a.x, b.y - a.y);
		const int n = std::max(1, static_cast<int>(std::ceil(len / step)));
		for (int k = 0; k < n; k++)
		{
			const double t = (k + 0.5) / n;
			visit({a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)}, len / n);
		}
	}
	if (path.size() == 1) visit(path.front(), 0);
}
}  // namespace

double pathLength(const Path& path)
{
	double sum = 0;
	for (size_t i = 0; i + 1 < path.size(); i++)
		sum += std::hypot(path[i + 1].x - path[i].x, path[i + 1].y - path[i].y);
	return sum;
}

double minimumClearance(const Path& path, const TraversableGrid& grid)
{
	double smallest = INFINITY;
	samplePath(path, grid.resolution() / 4, [&](const mrpt::math::TPoint2D& p, double) {
		smallest = std::min(smallest, grid.clearanceAt(p));
	});
	return smallest;
}

double lengthThroughObstacles(const Path& path, const TraversableGrid& grid)
{
	double inside = 0;
	samplePath(path, grid.resolution() / 4, [&](const mrpt::math::TPoint2D& p, double len) {
		if (grid.contains(p) && grid.isObstacle(grid.cellOf(p))) inside += len;
	});
	return inside;
}

}  // namespace lvf::planning
