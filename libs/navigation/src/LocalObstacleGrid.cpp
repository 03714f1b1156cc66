#include <lvfusion/navigation/LocalObstacleGrid.h>
#include <mrpt/poses/CPose3D.h>
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace lvf::navigation
{
namespace
{
/** Cell indices [x0, x1] x [y0, y1]: the square of half side `reach`
 * round (x, y), clipped to `grid` (empty when it lies outside). */
struct CellWindow
{
	int x0, y0, x1, y1;
	bool empty() const { return x0 > x1 || y0 > y1; }
};
CellWindow cellsAround(const mrpt::maps::COccupancyGridMap2D& grid, double x, double y, double reach)
{
	return {std::max(0, grid.x2idx(x - reach)), std::max(0, grid.y2idx(y - reach)),
		std::min(int(grid.getSizeX()) - 1, grid.x2idx(x + reach)), std::min(int(grid.getSizeY()) - 1, grid.y2idx(y + reach))};
}
}  // namespace

LocalObstacleGrid::LocalObstacleGrid(
	double xMin, double xMax, double yMin, double yMax, double resolution, double occupiedBelow,
	double visionMargin)
	: m_occupiedBelow(float(occupiedBelow)), m_visionMargin(visionMargin)
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
	keepOneGeometry();
}

void LocalObstacleGrid::insertVision(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::poses::CPose2D& robot)
{
	const mrpt::poses::CPose3D pose(robot);
	m_vision.insertObservation(scan, pose);
	keepOneGeometry();
}

void LocalObstacleGrid::markTraversed(const mrpt::poses::CPose2D& robot, double radius)
{
	const auto& g = m_vision;
	const CellWindow w = cellsAround(g, robot.x(), robot.y(), radius);
	for (int cy = w.y0; cy <= w.y1; cy++)
		for (int cx = w.x0; cx <= w.x1; cx++)
			if (std::hypot(g.idx2x(cx) - robot.x(), g.idx2y(cy) - robot.y()) <= radius) m_vision.setCell(cx, cy, 1.0f);
}

void LocalObstacleGrid::keepOneGeometry()
{
	const auto same = [](float a, float b) { return std::abs(a - b) < 1e-4f; };
	if (same(m_laser.getXMin(), m_vision.getXMin()) && same(m_laser.getXMax(), m_vision.getXMax()) &&
		same(m_laser.getYMin(), m_vision.getYMin()) && same(m_laser.getYMax(), m_vision.getYMax()))
		return;
	const float xMin = std::min(m_laser.getXMin(), m_vision.getXMin()), xMax = std::max(m_laser.getXMax(), m_vision.getXMax());
	const float yMin = std::min(m_laser.getYMin(), m_vision.getYMin()), yMax = std::max(m_laser.getYMax(), m_vision.getYMax());
	for (auto* g : {&m_laser, &m_vision}) g->resizeGrid(xMin, xMax, yMin, yMax, 0.5f, false);
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

cv::Mat1b LocalObstacleGrid::nearVisionOnly(double distance, int x0, int y0, int x1, int y1) const
{
	// The window padded by the reach, so that cells just outside it count.
	const int r = int(std::ceil(distance / m_laser.getResolution()));
	const int W = int(m_laser.getSizeX()), H = int(m_laser.getSizeY());
	cv::Mat1b visionOnly = cv::Mat1b::zeros(y1 - y0 + 1 + 2 * r, x1 - x0 + 1 + 2 * r);
	for (int cy = std::max(0, y0 - r); cy <= std::min(H - 1, y1 + r); cy++)
		for (int cx = std::max(0, x0 - r); cx <= std::min(W - 1, x1 + r); cx++)
			if (m_vision.getCell(cx, cy) < m_occupiedBelow && m_laser.getCell(cx, cy) >= m_occupiedBelow)
				visionOnly(cy - y0 + r, cx - x0 + r) = 255;
	cv::Mat1b near;
	cv::dilate(visionOnly, near, cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1)));
	return near(cv::Rect(r, r, x1 - x0 + 1, y1 - y0 + 1));
}

cv::Mat1b LocalObstacleGrid::assumedOverhang(double depth, int x0, int y0, int x1, int y1) const
{
	cv::Mat1b assumed = nearVisionOnly(depth, x0, y0, x1, y1);
	for (int cy = y0; cy <= y1; cy++)
	{
		// Log-odds 0: no observation ever reached the cell.
		const auto* vision = m_vision.getRow(cy);
		for (int cx = x0; cx <= x1; cx++)
		{
			uint8_t& cell = assumed(cy - y0, cx - x0);
			if (!cell || vision[cx] == 0) continue;
			const bool lookedThrough = m_overhangUnseenMinHeight <= 0 ||
				!unseen(m_vision.idx2x(cx), m_vision.idx2y(cy), m_overhangUnseenMinHeight);
			if (lookedThrough) cell = 0;
		}
	}
	return assumed;
}

void LocalObstacleGrid::assumeOverhangDepth(double depth, mrpt::maps::COccupancyGridMap2D& out) const
{
	const int W = int(m_laser.getSizeX()), H = int(m_laser.getSizeY());
	const cv::Mat1b assumed = assumedOverhang(depth, 0, 0, W - 1, H - 1);
	for (int cy = 0; cy < H; cy++)
		for (int cx = 0; cx < W; cx++)
			if (assumed(cy, cx)) out.setCell(cx, cy, 0.0f);
}

void LocalObstacleGrid::senseAssumedOverhangs(double depth, std::vector<Disk> open, double robotClearance)
{
	m_sensedOverhangDepth = depth;
	m_sensedOverhangOpen = std::move(open);
	m_sensedOverhangRobotClearance = robotClearance;
}

void LocalObstacleGrid::obstaclesNear(
	const mrpt::poses::CPose2D& robot, double range, mrpt::maps::CSimplePointsMap& out) const
{
	out.clear();
	const auto& g = m_laser;
	const CellWindow w = cellsAround(g, robot.x(), robot.y(), range);
	if (w.empty()) return;
	const int x0 = w.x0, y0 = w.y0, x1 = w.x1, y1 = w.y1;
	// What only vision found is grown by the margin (see the constructor).
	cv::Mat1b grown;
	if (m_visionMargin > 0) grown = nearVisionOnly(m_visionMargin, x0, y0, x1, y1);
	if (m_sensedOverhangDepth > 0)
	{
		cv::Mat1b assumed = assumedOverhang(m_sensedOverhangDepth, x0, y0, x1, y1);
		// The open disks, in cell units for cv::circle.
		const double cells = 1.0 / g.getResolution();
		auto open = [&](const Disk& d) {
			const cv::Point centre(
				int(std::lround((d.centre.x - g.idx2x(x0)) * cells)), int(std::lround((d.centre.y - g.idx2y(y0)) * cells)));
			cv::circle(assumed, centre, int(std::ceil(d.radius * cells)), cv::Scalar(0), cv::FILLED);
		};
		open({{robot.x(), robot.y()}, m_sensedOverhangRobotClearance});
		for (const Disk& d : m_sensedOverhangOpen) open(d);
		if (grown.empty()) grown = assumed;
		else cv::bitwise_or(grown, assumed, grown);
	}
	const double r2 = range * range;
	for (int cy = y0; cy <= y1; cy++)
		for (int cx = x0; cx <= x1; cx++)
		{
			if (!obstacle(cx, cy) && (grown.empty() || !grown(cy - y0, cx - x0))) continue;
			const double x = g.idx2x(cx), y = g.idx2y(cy);
			const double dx = x - robot.x(), dy = y - robot.y();
			if (dx * dx + dy * dy > r2) continue;
			const auto local = robot.inverseComposePoint(mrpt::math::TPoint2D(x, y));
			out.insertPoint(float(local.x), float(local.y), 0.0f);
		}
}

}  // namespace lvf::navigation

namespace lvf::navigation
{
void LocalObstacleGrid::trackSeenSpace(const lvf::HeightBand& band)
{
	m_seen = std::make_unique<SeenSpace>(
		m_laser.getXMin(), m_laser.getXMax(), m_laser.getYMin(), m_laser.getYMax(), band, m_laser.getResolution());
}

bool LocalObstacleGrid::unseen(double x, double y, double minHeight) const
{
	return m_seen && m_seen->unseenHeight(x, y) >= minHeight - 1e-9;
}

void LocalObstacleGrid::assumeUnseenNear(
	const mrpt::math::TPoint2D& robot, double from, double radius, double minHeight,
	mrpt::maps::COccupancyGridMap2D& out) const
{
	if (!m_seen) return;
	const CellWindow w = cellsAround(out, robot.x, robot.y, radius);
	for (int cy = w.y0; cy <= w.y1; cy++)
		for (int cx = w.x0; cx <= w.x1; cx++)
		{
			const double x = out.idx2x(cx), y = out.idx2y(cy), d = std::hypot(x - robot.x, y - robot.y);
			if (d >= from && d <= radius && unseen(x, y, minHeight)) out.setCell(cx, cy, 0.0f);
		}
}

}  // namespace lvf::navigation
