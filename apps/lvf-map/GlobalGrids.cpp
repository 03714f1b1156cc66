#include "GlobalGrids.h"

#include <lvfusion/common/GridInsertion.h>
#include <lvfusion/common/LaserRange.h>
#include <opencv2/imgproc.hpp>

#include <cmath>

namespace lvf::apps
{
GlobalGrids::GlobalGrids(double resolution, int visualMinHits)
	: m_laser(-1, 1, -1, 1, static_cast<float>(resolution)),
	  m_fused(-1, 1, -1, 1, static_cast<float>(resolution)),
	  m_resolution(resolution),
	  m_visualMinHits(visualMinHits)
{
}

bool GlobalGrids::add(
	const mrpt::obs::CObservation2DRangeScan& laser, const mrpt::obs::CObservation2DRangeScan* fused,
	const mrpt::poses::CPose2D& pose)
{
	if (!lvf::common::insertScansAt(pose, m_laserScans == 0, {{&m_laser, &laser}, {&m_fused, fused}})) return false;
	m_laserScans++;
	if (fused)
	{
		m_fusedScans++;
		const mrpt::poses::CPose3D sensor = mrpt::poses::CPose3D(pose) + fused->sensorPose;
		for (size_t i = 0; i < fused->getScanSize() && i < laser.getScanSize(); i++)
		{
			const float r = fused->getScanRange(i);
			const float l = lvf::laserRangeOrMax(laser, i);
			if (!fused->getScanRangeValidity(i) || !(r < l - 0.5 * m_resolution)) continue;  // not vision's
			const double a = fused->getScanAngle(i);
			mrpt::math::TPoint3D end;
			sensor.composePoint(r * std::cos(a), r * std::sin(a), 0, end.x, end.y, end.z);
			m_visualHits[{static_cast<int>(std::floor(end.x / m_resolution)),
						  static_cast<int>(std::floor(end.y / m_resolution))}]++;
		}
	}
	return true;
}

void GlobalGrids::finish()
{
	for (const auto& [cell, hits] : m_visualHits)
		if (hits >= m_visualMinHits)
			m_fused.setPos(
				static_cast<float>((cell.first + 0.5) * m_resolution),
				static_cast<float>((cell.second + 0.5) * m_resolution), 0.0f);
}

cv::Mat3b drawPathsOnGrid(
	const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<DrawnPath>& paths,
	const mrpt::math::TPoint2D& start, const mrpt::math::TPoint2D& goal)
{
	mrpt::img::CImage img;
	grid.getAsImage(img, true, true);	 // flipped: row = cell y (south up), RGB
	cv::Mat3b picture = img.asCvMat<cv::Mat>(mrpt::img::DEEP_COPY);
	const double res = grid.getResolution();
	auto pixel = [&](const mrpt::math::TPoint2D& p) {
		return cv::Point(
			cvRound((p.x - grid.getXMin()) / res - 0.5), cvRound((p.y - grid.getYMin()) / res - 0.5));
	};
	for (const auto& path : paths)
		for (size_t i = 0; i + 1 < path.points.size(); i++)
			cv::line(picture, pixel(path.points[i]), pixel(path.points[i + 1]), path.colour, 1, cv::LINE_AA);
	cv::circle(picture, pixel(start), 3, {255, 0, 0}, cv::FILLED);
	cv::drawMarker(picture, pixel(goal), {255, 0, 0}, cv::MARKER_CROSS, 9, 2);
	cv::flip(picture, picture, 0);	// north up
	return picture;
}

}  // namespace lvf::apps
