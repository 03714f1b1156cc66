#include <lvfusion/metrics/ScanOnMap.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>

namespace lvf::metrics
{
namespace
{
bool occupiedNear(const mrpt::maps::COccupancyGridMap2D& map, int cx, int cy)
{
	for (int y = cy - 1; y <= cy + 1; y++)
		for (int x = cx - 1; x <= cx + 1; x++)
			if (x >= 0 && y >= 0 && x < int(map.getSizeX()) && y < int(map.getSizeY()) && map.getCell(x, y) < 0.5f)
				return true;
	return false;
}
}  // namespace

double scanShareOnMap(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot,
	const mrpt::maps::COccupancyGridMap2D& map, double maxRange, size_t rayStep)
{
	const mrpt::poses::CPose3D sensor = mrpt::poses::CPose3D(robot) + scan.sensorPose;
	size_t returns = 0, onMap = 0;
	for (size_t i = 0; i < scan.getScanSize(); i += std::max<size_t>(1, rayStep))
	{
		const double range = scan.getScanRange(i), a = scan.getScanAngle(i);
		if (!scan.getScanRangeValidity(i) || !(range > 0) || range > maxRange) continue;
		double x, y, z;
		sensor.composePoint(range * std::cos(a), range * std::sin(a), 0, x, y, z);
		returns++;
		onMap += occupiedNear(map, map.x2idx(x), map.y2idx(y));
	}
	return returns ? double(onMap) / double(returns) : 1.0;
}

}  // namespace lvf::metrics
