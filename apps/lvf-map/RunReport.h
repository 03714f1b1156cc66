#pragma once
// lvf-map's summary lines about its results, and, beside a simulated run
// (NAME_gt_poses.txt, NAME_obstacles.gridmap.gz next to the input), how they
// compare with the simulator's truth.

#include "MapPlans.h"

#include <lvfusion/metrics/PoseTrajectory.h>

#include <ostream>
#include <string>
#include <vector>

namespace lvf::apps
{
void printRunReport(
	std::ostream& out, const std::string& input, const std::vector<lvf::metrics::StampedPose>& poses,
	const std::vector<MapPlan>& plans, const Endpoints& ends);

}  // namespace lvf::apps
