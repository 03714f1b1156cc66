#pragma once
// The ground truth lvf-import-middlebury writes beside its rawlog, in exactly
// the formats of lvf-simulate (apps/lvf-simulate/GroundTruthWriter.cpp), so
// that lvf-fuse and lvf::metrics::readTruthScans read both alike:
//   NAME_gt_poses.txt     "frame timestamp x y yaw": the one frame's robot,
//                         at the origin of its own (virtual) world
//   NAME_truth_scans.csv  "frame,timestamp,b<bearing deg>,...", then the
//                         frame's truth scan ("inf": nothing in the band)

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <string>
#include <vector>

namespace lvf::apps
{
void writeGroundTruthPose(const std::string& path, mrpt::Clock::time_point stamp);

/** `truth` has one range per ray of `scan`; the header names the bearings. */
void writeTruthScan(
	const std::string& path, const mrpt::obs::CObservation2DRangeScan& scan,
	const std::vector<float>& truth);

}  // namespace lvf::apps
