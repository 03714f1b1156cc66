#pragma once
// lvf-fuse's results besides the output rawlog:
//   NAME_fused.gridmap.gz / NAME_laser.gridmap.gz  local occupancy grids
//   NAME_grids.png     laser-only (left) and fused (right), as paper Figs. 9, 11d-e
//   NAME_frames.csv    per frame: stage times, pixel counts, obstacle counts,
//                      and recall / phantom rate when a truth scan is known
//   NAME_bearings.csv  per frame and laser bearing: laser, visual, fused and
//                      truth range, in view, hidden -- to see where it errs
//   NAME_points.csv    (asked for) per frame, every visual point the fused
//                      scan was made from -- to see why a bearing got its range

#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/common/WrittenFiles.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservationImage.h>

#include <optional>

namespace lvf::apps
{
/** The evaluation picture of a frame (label EVAL): the model check's tints
 * (inconsistent red, unmodelled magenta, unjudged blue), then the search's
 * pixels: rejected orange, visual obstacle points yellow. */
mrpt::obs::CObservationImage::Ptr evaluationImage(
	const lvf::fusion::CLaserStereoFusion::Result& r, mrpt::Clock::time_point stamp);

/** A frame's truth scan and what it says of the fused scan. */
struct FrameTruth
{
	std::vector<float> ranges;	//!< per bearing [m], inf: nothing in the band
	std::vector<float> seenRanges;	//!< the same of what both cameras see; empty: not known
	std::vector<bool> inView, hidden;  //!< DESIGN.md's, at any range
	/** How each bearing counts in `score` (up to Zmax). */
	std::vector<lvf::metrics::BearingVerdict> verdicts;
	lvf::metrics::FusionScore score;
};

class FusionOutputs
{
   public:
	/** `writePoints`: also NAME_points.csv (large: thousands of rows a frame). */
	FusionOutputs(
		lvf::common::StagedOutputFiles& files, const std::string& name, double gridResolution, bool writePoints = false);

	/** Inserts both scans at the odometry pose and logs the frame's figures.
	 * False when the scans' pose could not go into a grid
	 * (lvf::common::insertableInGrid): the frame is logged, not inserted. */
	bool add(
		size_t frame, const mrpt::obs::CObservation2DRangeScan& laser,
		const lvf::fusion::CLaserStereoFusion::Result& r, const mrpt::poses::CPose2D& odometry,
		const std::optional<FrameTruth>& truth);
	void close();

   private:
	lvf::common::StagedOutputFiles& m_files;
	std::string m_name;
	mrpt::maps::COccupancyGridMap2D m_laserGrid, m_fusedGrid;
	size_t m_inserted = 0;	//!< frames in the grids
	lvf::common::OutputFile m_csv, m_bearingsCsv, m_pointsCsv;  // the last open only if asked for

	void addBearings(
		size_t frame, const mrpt::obs::CObservation2DRangeScan& laser,
		const lvf::fusion::CLaserStereoFusion::Result& r, const std::optional<FrameTruth>& truth);
	void addPoints(
		size_t frame, const mrpt::obs::CObservation2DRangeScan& laser, const lvf::fusion::CLaserStereoFusion::Result& r);
};

}  // namespace lvf::apps
