#include <lvfusion/metrics/ObstacleGridScore.h>

#include <cmath>

namespace lvf::metrics
{
namespace
{
/** Any cell within `radius` [m] of (x, y) satisfying `test`. */
template <typename Test>
bool anyNear(const mrpt::maps::COccupancyGridMap2D& g, double x, double y, double radius, Test test)
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
}  // namespace

ObstacleGridScore scoreObstacleGrid(
	const mrpt::maps::COccupancyGridMap2D& map, const mrpt::maps::COccupancyGridMap2D& truth,
	double tolerance, double margin)
{
	const auto occupied = [margin](float p) { return p < 0.5f - margin; };
	const auto observed = [margin](float p) { return std::abs(p - 0.5f) > margin; };
	ObstacleGridScore s;
	for (unsigned cy = 0; cy < truth.getSizeY(); cy++)
		for (unsigned cx = 0; cx < truth.getSizeX(); cx++)
		{
			if (!occupied(truth.getCell(cx, cy))) continue;
			const double x = truth.idx2x(cx), y = truth.idx2y(cy);
			if (!anyNear(map, x, y, 0, observed)) continue;
			s.truthObserved++;
			s.truthFound += anyNear(map, x, y, tolerance, occupied);
		}
	for (unsigned cy = 0; cy < map.getSizeY(); cy++)
		for (unsigned cx = 0; cx < map.getSizeX(); cx++)
		{
			if (!occupied(map.getCell(cx, cy))) continue;
			s.mapOccupied++;
			s.mapCorrect += anyNear(truth, map.idx2x(cx), map.idx2y(cy), tolerance, occupied);
		}
	return s;
}

}  // namespace lvf::metrics
