#pragma once
// Robot trajectories as text, "frame timestamp x y yaw" per line (the format
// of lvf-simulate's NAME_gt_poses.txt and lvf-map's NAME_poses.txt), and how
// far one is from another.

#include <mrpt/poses/CPose2D.h>

#include <string>
#include <vector>

namespace lvf::metrics
{
struct StampedPose
{
	size_t frame = 0;
	double timestamp = 0;  //!< [s]
	mrpt::poses::CPose2D pose;
};

/** Throws lvf::common::InputError naming the file and line if malformed. */
std::vector<StampedPose> readPoseFile(const std::string& path);
void writePoseFile(const std::string& path, const std::vector<StampedPose>& poses);

struct TrajectoryError
{
	size_t matched = 0;	 //!< poses of the estimate with a truth pose of the same timestamp
	double medianPosition = 0;	//!< [m]
	double medianHeading = 0;  //!< [rad]
	double maxPosition = 0;	 //!< [m]
};

/** The pose of `poses` stamped within 1e-4 s of `timestamp`; null if none. */
const StampedPose* poseStampedAt(const std::vector<StampedPose>& poses, double timestamp);

/** Errors of `estimate` against the `truth` pose stamped within 1e-4 s of
 * it, the estimate's frame lying at `estimateInTruth` in the truth's. */
TrajectoryError compareTrajectories(
	const std::vector<StampedPose>& estimate, const std::vector<StampedPose>& truth,
	const mrpt::poses::CPose2D& estimateInTruth = {});

}  // namespace lvf::metrics
