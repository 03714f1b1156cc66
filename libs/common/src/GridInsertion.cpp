#include <lvfusion/common/GridInsertion.h>

#include <algorithm>
#include <cmath>

namespace lvf::common
{
void startGridAround(mrpt::maps::COccupancyGridMap2D& grid, double x, double y)
{
	if (!std::isfinite(x) || !std::isfinite(y)) return;
	grid.setSize(
		static_cast<float>(x - 1), static_cast<float>(x + 1), static_cast<float>(y - 1), static_cast<float>(y + 1),
		grid.getResolution());
}

bool insertableInGrid(
	const mrpt::maps::COccupancyGridMap2D& grid, const mrpt::poses::CPose3D& robot,
	const mrpt::obs::CObservation2DRangeScan& scan)
{
	const mrpt::poses::CPose3D sensor = robot + scan.sensorPose;
	for (const double v : {sensor.x(), sensor.y(), sensor.z(), sensor.yaw(), sensor.pitch(), sensor.roll()})
		if (!std::isfinite(v)) return false;
	const double reach = kMaxGridGrowth + std::max(0.0f, scan.maxRange);
	const double outsideX = std::max({0.0, grid.getXMin() - sensor.x(), sensor.x() - grid.getXMax()});
	const double outsideY = std::max({0.0, grid.getYMin() - sensor.y(), sensor.y() - grid.getYMax()});
	return outsideX <= reach && outsideY <= reach;
}

bool insertScansAt(const mrpt::poses::CPose2D& pose, bool first, std::initializer_list<GridAndScan> gridsAndScans)
{
	if (first)
		for (const auto& [grid, scan] : gridsAndScans) startGridAround(*grid, pose.x(), pose.y());
	const mrpt::poses::CPose3D robot(pose);
	for (const auto& [grid, scan] : gridsAndScans)
		if (scan && !insertableInGrid(*grid, robot, *scan)) return false;
	for (const auto& [grid, scan] : gridsAndScans)
		if (scan) grid->insertObservation(*scan, robot);
	return true;
}

}  // namespace lvf::common
