#include <lvfusion/metrics/ObstacleGridScore.h>
#include "GridNeighbourhood.h"

#include <cmath>

namespace lvf::metrics
{
ObstacleGridScore scoreObstacleGrid(
	const mrpt::maps::COccupancyGridMap2D& map, const mrpt::maps::COccupancyGridMap2D& truth,
	const mrpt::poses::CPose2D& mapInTruth, double tolerance, double margin)
{
	const auto occupied = [margin](float p) { return p < 0.5f - margin; };
	const auto observed = [margin](float p) { return std::abs(p - 0.5f) > margin; };
	const auto truthInMap = -mapInTruth;
	ObstacleGridScore s;
	for (unsigned cy = 0; cy < truth.getSizeY(); cy++)
		for (unsigned cx = 0; cx < truth.getSizeX(); cx++)
		{
			if (!occupied(truth.getCell(cx, cy))) continue;
			const auto inMap = truthInMap + mrpt::math::TPoint2D(truth.idx2x(cx), truth.idx2y(cy));
			if (!anyCellNear(map, inMap.x, inMap.y, 0, observed)) continue;
			s.truthObserved++;
			s.truthFound += anyCellNear(map, inMap.x, inMap.y, tolerance, occupied);
		}
	for (unsigned cy = 0; cy < map.getSizeY(); cy++)
		for (unsigned cx = 0; cx < map.getSizeX(); cx++)
		{
			if (!occupied(map.getCell(cx, cy))) continue;
			s.mapOccupied++;
			const auto inTruth = mapInTruth + mrpt::math::TPoint2D(map.idx2x(cx), map.idx2y(cy));
			s.mapCorrect += anyCellNear(truth, inTruth.x, inTruth.y, tolerance, occupied);
		}
	return s;
}

}  // namespace lvf::metrics
