#pragma once
// The ground truth lvf-simulate writes beside its rawlog (all openable by a
// person or a script; formats documented in the README):
//   NAME_gt_poses.txt          frame, timestamp, true x y yaw
//   NAME_truth_scans.csv       per frame, the truth scan of every laser bearing
//   NAME_seen_truth_scans.csv  the same of what both cameras see (StereoSeenTruth.h)
//   NAME_obstacles.gridmap.gz  robot-band obstacles, COccupancyGridMap2D
//   NAME_obstacles.png         the same as an image
//   NAME_depth/NNNNNN.pfm      left-image depth [m] (with --depth)
// (and main.cpp adds NAME_preview.png, see PreviewImage.h)

#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/common/WrittenFiles.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>

#include <string>

namespace lvf::apps
{
class GroundTruthWriter
{
   public:
	GroundTruthWriter(
		lvf::common::StagedOutputFiles& files, const std::string& name,
		bool writeDepth);

	/** Needs the frame's depth (simulated with it) for the seen truth. */
	void add(const lvf::simulation::CStereoLaserSimulator::Frame& frame);
	void writeObstacleMap(const lvf::simulation::World& world);
	void close();

   private:
	lvf::common::StagedOutputFiles& m_files;
	std::string m_name;
	bool m_writeDepth;
	lvf::common::OutputFile m_poses, m_truth, m_seenTruth;
};

}  // namespace lvf::apps
