#include <lvfusion/metrics/ScanOnMap.h>
#include <mrpt/poses/CPose3D.h>
#include "GridNeighbourhood.h"

#include <algorithm>
#include <cmath>

namespace lvf::metrics
{
double scanShareOnMap(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot,
	const mrpt::maps::COccupancyGridMap2D& map, double maxRange, size_t rayStep)
{
	const mrpt::poses::CPose3D sensor = mrpt::poses::CPose3D(robot) + scan.sensorPose;
	// Within a cell: the eight cells round the one the return falls in.
	const double withinACell = std::sqrt(2.0) * map.getResolution();
	const auto occupied = [](float p) { return p < 0.5f; };
	size_t returns = 0, onMap = 0;
	for (size_t i = 0; i < scan.getScanSize(); i += std::max<size_t>(1, rayStep))
	{
		const double range = scan.getScanRange(i), a = scan.getScanAngle(i);
		if (!scan.getScanRangeValidity(i) || !(range > 0) || range > maxRange) continue;
		double x, y, z;
		sensor.composePoint(range * std::cos(a), range * std::sin(a), 0, x, y, z);
		returns++;
		onMap += anyCellNear(map, x, y, withinACell, occupied);
	}
	return returns ? double(onMap) / double(returns) : 1.0;
}

}  // namespace lvf::metrics
