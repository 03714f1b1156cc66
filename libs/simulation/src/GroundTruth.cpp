#include <lvfusion/simulation/GroundTruth.h>
#include <lvfusion/simulation/WorldGeometry.h>

#include <cmath>
#include <limits>

namespace lvf::simulation
{
namespace
{
std::vector<const Box*> bandBoxes(const World& world)
{
	std::vector<const Box*> out;
	for (const auto& b : world.boxes)
		if (b.overlapsHeights(world.robot.obstacleMinHeight, world.robot.height))
			out.push_back(&b);
	return out;
}

/** Range along a horizontal ray to a box footprint; 0 inside, inf if missed. */
double footprintRange(
	const Box& b, double ox, double oy, double dirX, double dirY)
{
	const double c = std::cos(b.yaw), s = std::sin(b.yaw);
	const double o[2] = {
		c * (ox - b.x) + s * (oy - b.y), -s * (ox - b.x) + c * (oy - b.y)};
	const double d[2] = {c * dirX + s * dirY, -s * dirX + c * dirY};
	const double half[2] = {0.5 * b.sizeX, 0.5 * b.sizeY};
	if (std::abs(o[0]) <= half[0] && std::abs(o[1]) <= half[1]) return 0;
	double t;
	int axis;
	return intersectSlabs(o, d, half, 2, t, axis)
		? t
		: std::numeric_limits<double>::infinity();
}

/** Separating-axis test: does the axis-aligned square overlap the footprint? */
bool cellOverlapsFootprint(
	const Box& b, double cellX, double cellY, double halfCell)
{
	const double c = std::cos(b.yaw), s = std::sin(b.yaw);
	const double hx = 0.5 * b.sizeX, hy = 0.5 * b.sizeY;
	const double dx = cellX - b.x, dy = cellY - b.y;
	// World axes: the footprint's half-width along x and y.
	const double extentX = std::abs(c) * hx + std::abs(s) * hy;
	const double extentY = std::abs(s) * hx + std::abs(c) * hy;
	if (std::abs(dx) > extentX + halfCell || std::abs(dy) > extentY + halfCell)
		return false;
	// Box axes: the square's half-width along the box's own axes.
	const double squareExtent = (std::abs(c) + std::abs(s)) * halfCell;
	const double lx = c * dx + s * dy, ly = -s * dx + c * dy;
	return std::abs(lx) <= hx + squareExtent && std::abs(ly) <= hy + squareExtent;
}

}  // namespace

std::vector<float> truthScan(
	const World& world, const mrpt::poses::CPose3D& robotPose,
	const mrpt::obs::CObservation2DRangeScan& scanGeometry)
{
	const auto boxes = bandBoxes(world);
	const mrpt::poses::CPose3D sensor = robotPose + scanGeometry.sensorPose;
	const size_t n = scanGeometry.getScanSize();
	std::vector<float> ranges(n, std::numeric_limits<float>::infinity());
	for (size_t i = 0; i < n; i++)
	{
		const double bearing = sensor.yaw() - 0.5 * scanGeometry.aperture +
			scanGeometry.aperture * static_cast<double>(i) /
				static_cast<double>(n > 1 ? n - 1 : 1);
		const double dx = std::cos(bearing), dy = std::sin(bearing);
		double best = std::numeric_limits<double>::infinity();
		for (const Box* b : boxes)
			best = std::min(best, footprintRange(*b, sensor.x(), sensor.y(), dx, dy));
		ranges[i] = static_cast<float>(best);
	}
	return ranges;
}

mrpt::maps::COccupancyGridMap2D obstacleGrid(
	const World& world, double resolution, double margin)
{
	double xMin, xMax, yMin, yMax;
	world.footprintBounds(xMin, xMax, yMin, yMax, margin);
	mrpt::maps::COccupancyGridMap2D grid(
		static_cast<float>(xMin), static_cast<float>(xMax),
		static_cast<float>(yMin), static_cast<float>(yMax),
		static_cast<float>(resolution));
	grid.fill(1.0f);  // free
	const double halfCell = 0.5 * grid.getResolution();
	for (const Box* b : bandBoxes(world))
	{
		const double reach = 0.5 * std::hypot(b->sizeX, b->sizeY) + halfCell;
		const int cx0 = std::max(0, grid.x2idx(b->x - reach));
		const int cx1 = std::min(int(grid.getSizeX()) - 1, grid.x2idx(b->x + reach));
		const int cy0 = std::max(0, grid.y2idx(b->y - reach));
		const int cy1 = std::min(int(grid.getSizeY()) - 1, grid.y2idx(b->y + reach));
		for (int cy = cy0; cy <= cy1; cy++)
			for (int cx = cx0; cx <= cx1; cx++)
				if (cellOverlapsFootprint(
						*b, grid.idx2x(cx), grid.idx2y(cy), halfCell))
					grid.setCell(cx, cy, 0.0f);
	}
	return grid;
}

}  // namespace lvf::simulation
