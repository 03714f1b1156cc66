#pragma once
// The plans of lvf-map (one per global map) and the files they are written
// to: per map NAME_<map>_map.{gridmap.gz,png} and NAME_<map>_path.txt,
// NAME_paths.png (Fig. 14c-d: every path over every map) and NAME_plans.csv.

#include "RequestedEndpoints.h"

#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/planning/ValueIterationPlanner.h>
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace lvf::apps
{
struct Endpoints
{
	mrpt::math::TPoint2D start, goal;
};

struct MapPlan
{
	std::string name;  //!< "laser" or "fused"
	const mrpt::maps::COccupancyGridMap2D* grid = nullptr;
	lvf::planning::ValueIterationPlanner::Result plan;
	cv::Scalar colour;	//!< of its path in the pictures (BGR)
};

/** Plans on each map. A start or goal the user gave must be usable (an
 * InputError naming where it came from otherwise); the run's own first and
 * last poses may not be (then the summary says why there is no path). */
void planOnEachGrid(
	std::vector<MapPlan>& plans, const Endpoints& ends, const RequestedEndpoints& requested,
	const lvf::planning::ValueIterationPlanner::TOptions& options);

void writeMapPlans(
	lvf::common::StagedOutputFiles& files, const std::string& name, const std::vector<MapPlan>& plans,
	const Endpoints& ends, const lvf::planning::ValueIterationPlanner::TOptions& planner);

}  // namespace lvf::apps
