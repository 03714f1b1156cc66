#pragma once
// The global maps of paper §7 / Fig. 14a-b: every laser scan, and every fused
// scan, inserted at the robot's localised pose into its own
// COccupancyGridMap2D (MRPT's insertion: free along each ray, occupied at its
// end); and the pictures of Fig. 14c-d, both planned paths over both maps.
//
// Visual obstacles are sticky in the fused map. Free space along a laser ray
// is free space in the laser's plane only, not in the robot's height band:
// a desk top vision found from one pose would otherwise be erased by the
// many later scans (or frames where vision did not look there) whose rays
// pass under it. So every cell where vision ended `visualMinHits` fused
// bearings (bearings vision made shorter than the laser's) is marked
// occupied after all scans are in.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <opencv2/core.hpp>

#include <map>
#include <string>
#include <vector>

namespace lvf::apps
{
class GlobalGrids
{
   public:
	GlobalGrids(double resolution, int visualMinHits);
	/** False, and nothing added, when the scan's pose could not go into a
	 * grid (lvf::common::insertableInGrid). */
	bool add(
		const mrpt::obs::CObservation2DRangeScan& laser, const mrpt::obs::CObservation2DRangeScan* fused,
		const mrpt::poses::CPose2D& pose);
	/** Marks the visual obstacle cells occupied; call once, after every add(). */
	void finish();

	const mrpt::maps::COccupancyGridMap2D& laser() const { return m_laser; }
	const mrpt::maps::COccupancyGridMap2D& fused() const { return m_fused; }
	size_t fusedScans() const { return m_fusedScans; }

   private:
	mrpt::maps::COccupancyGridMap2D m_laser, m_fused;
	size_t m_laserScans = 0, m_fusedScans = 0;
	double m_resolution;
	int m_visualMinHits;
	std::map<std::pair<int, int>, int> m_visualHits;	 // world cell -> bearings ending there
};

struct DrawnPath
{
	std::vector<mrpt::math::TPoint2D> points;
	cv::Scalar colour;	//!< BGR
};

/** The grid as a picture (north up), with each path drawn over it, start
 * and goal marked. */
cv::Mat3b drawPathsOnGrid(
	const mrpt::maps::COccupancyGridMap2D& grid, const std::vector<DrawnPath>& paths,
	const mrpt::math::TPoint2D& start, const mrpt::math::TPoint2D& goal);

}  // namespace lvf::apps
