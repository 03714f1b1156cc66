#include <lvfusion/navigation/LocalObstacleGrid.h>
#include <mrpt/poses/CPose3D.h>
#include <algorithm>

namespace lvf::navigation
{
LocalObstacleGrid::LocalObstacleGrid(
	double xMin, double xMax, double yMin, double yMax, double resolution, double occupiedBelow)
	: m_occupiedBelow(float(occupiedBelow))
{
	for (auto* g : {&m_laser, &m_vision})
		g->setSize(float(xMin), float(xMax), float(yMin), float(yMax), float(resolution), 0.5f);
	m_vision.insertionOptions.considerInvalidRangesAsFreeSpace = false;
}

void LocalObstacleGrid::insertLaser(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot)
{
	const mrpt::poses::CPose3D pose(robot);
	m_laser.insertObservation(scan, pose);
}

void LocalObstacleGrid::insertVision(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot)
{
	const mrpt::poses::CPose3D pose(robot);
	m_vision.insertObservation(scan, pose);
}

bool LocalObstacleGrid::obstacle(int cx, int cy) const
{
	return m_laser.getCell(cx, cy) < m_occupiedBelow || m_vision.getCell(cx, cy) < m_occupiedBelow;
}

mrpt::maps::COccupancyGridMap2D LocalObstacleGrid::obstacleMap() const
{
	mrpt::maps::COccupancyGridMap2D out = m_laser;
	for (unsigned cy = 0; cy < m_laser.getSizeY(); cy++)
		for (unsigned cx = 0; cx < m_laser.getSizeX(); cx++)
			out.setCell(int(cx), int(cy), std::min(m_laser.getCell(int(cx), int(cy)), m_vision.getCell(int(cx), int(cy))));
	return out;
}

void LocalObstacleGrid::obstaclesNear(
	const mrpt::poses::CPose2D& robot, double range, mrpt::maps::CSimplePointsMap& out) const
{
	out.clear();
	const auto& g = m_laser;
	const int x0 = std::max(0, g.x2idx(robot.x() - range));
	const int x1 = std::min(int(g.getSizeX()) - 1, g.x2idx(robot.x() + range));
	const int y0 = std::max(0, g.y2idx(robot.y() - range));
	const int y1 = std::min(int(g.getSizeY()) - 1, g.y2idx(robot.y() + range));
	const double r2 = range * range;
	for (int cy = y0; cy <= y1; cy++)
		for (int cx = x0; cx <= x1; cx++)
		{
			if (!obstacle(cx, cy)) continue;
			const double x = g.idx2x(cx), y = g.idx2y(cy);
			const double dx = x - robot.x(), dy = y - robot.y();
			if (dx * dx + dy * dy > r2) continue;
			const auto local = robot.inverseComposePoint(mrpt::math::TPoint2D(x, y));
			out.insertPoint(float(local.x), float(local.y), 0.0f);
		}
}

}  // namespace lvf::navigation
