#pragma once
// lvf-fuse's results besides the output rawlog:
//   NAME_fused.gridmap.gz / NAME_laser.gridmap.gz  local occupancy grids
//   NAME_grids.png     laser-only (left) and fused (right), as paper Figs. 9, 11d-e
//   NAME_frames.csv    per frame: stage times, pixel counts, obstacle counts,
//                      and recall / phantom rate when a truth scan is known
//   NAME_bearings.csv  per frame and laser bearing: laser, visual, fused and
//                      truth range, in view, hidden -- to see where it errs

#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservationImage.h>

#include <fstream>
#include <optional>

namespace lvf::apps
{
/** The evaluation picture of a frame (label EVAL): inconsistent pixels red,
 * unjudged blue, visual obstacle points yellow. */
mrpt::obs::CObservationImage::Ptr evaluationImage(
	const lvf::fusion::CLaserStereoFusion::Result& r, mrpt::Clock::time_point stamp);

/** A frame's truth scan and what it says of the fused scan. */
struct FrameTruth
{
	std::vector<float> ranges;	//!< per bearing [m], inf: nothing in the band
	std::vector<float> seenRanges;	//!< the same of what both cameras see; empty: not known
	std::vector<bool> inView, hidden;
	lvf::metrics::FusionScore score;
};

class FusionOutputs
{
   public:
	FusionOutputs(lvf::common::StagedOutputFiles& files, const std::string& name, double gridResolution);

	/** Inserts both scans at the odometry pose and logs the frame's figures. */
	void add(
		size_t frame, const mrpt::obs::CObservation2DRangeScan& laser,
		const lvf::fusion::CLaserStereoFusion::Result& r, const mrpt::poses::CPose2D& odometry,
		const std::optional<FrameTruth>& truth);
	void close();

   private:
	lvf::common::StagedOutputFiles& m_files;
	std::string m_name;
	mrpt::maps::COccupancyGridMap2D m_laserGrid, m_fusedGrid;
	std::ofstream m_csv, m_bearingsCsv;

	void addBearings(
		size_t frame, const mrpt::obs::CObservation2DRangeScan& laser,
		const lvf::fusion::CLaserStereoFusion::Result& r, const std::optional<FrameTruth>& truth);
};

}  // namespace lvf::apps
