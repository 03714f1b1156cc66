#include <lvfusion/metrics/ObstacleGridScore.h>
#include "GridNeighbourhood.h"

#include <cmath>

namespace lvf::metrics
{
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
			if (!anyCellNear(map, x, y, 0, observed)) continue;
			s.truthObserved++;
			s.truthFound += anyCellNear(map, x, y, tolerance, occupied);
		}
	for (unsigned cy = 0; cy < map.getSizeY(); cy++)
		for (unsigned cx = 0; cx < map.getSizeX(); cx++)
		{
			if (!occupied(map.getCell(cx, cy))) continue;
			s.mapOccupied++;
			s.mapCorrect += anyCellNear(truth, map.idx2x(cx), map.idx2y(cy), tolerance, occupied);
		}
	return s;
}

}  // namespace lvf::metrics
