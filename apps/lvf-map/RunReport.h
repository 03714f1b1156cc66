#pragma once
// lvf-map's summary lines about its results, and, beside a simulated run
// (NAME_gt_poses.txt, NAME_obstacles.gridmap.gz next to the input), how they
// compare with the simulator's truth.

#include "MapPlans.h"

#include <lvfusion/metrics/PoseTrajectory.h>
#include <mrpt/maps/COccupancyGridMap2D.h>

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace lvf::apps
{
/** The simulator's truth beside a run, where there is some. */
struct RunTruth
{
	std::optional<std::string> posesPath;  //!< NAME_gt_poses.txt
	std::vector<lvf::metrics::StampedPose> poses;
	std::optional<std::string> obstaclesPath;  //!< NAME_obstacles.gridmap.gz
	std::optional<mrpt::maps::COccupancyGridMap2D> obstacles;
};

/** Reads the truth files beside `input` (before the work: one that cannot
 * be read is an InputError, not a report cut short). */
RunTruth loadRunTruth(const std::string& input);

void printRunReport(
	std::ostream& out, const RunTruth& truth, const std::vector<lvf::metrics::StampedPose>& poses,
	const std::vector<MapPlan>& plans, const Endpoints& ends);

}  // namespace lvf::apps
