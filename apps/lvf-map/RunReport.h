#pragma once
// lvf-map's summary lines about its results, and, beside a simulated run
// (NAME_gt_poses.txt, NAME_obstacles.gridmap.gz next to the input), how they
// compare with the simulator's truth.

#include "MapPlans.h"
#include "MapRun.h"

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

/** Where the frame of lvf-map's poses, grids and paths lies in the truth's
 * (the simulated world's). A prior map the user gives is taken to be drawn in
 * the world's frame. A map built from the run is in the run's odometry frame,
 * which a sensory-frame log starts at the origin wherever the robot is: it is
 * placed by the first scan, whose pose in the world is the truth pose of its
 * time, else the world file's first path pose (`worldStart`), composed with
 * the inverse of its odometry. nullopt when neither is known. */
std::optional<mrpt::poses::CPose2D> mapFrameInTruth(
	const RunTruth& truth, const std::optional<mrpt::poses::CPose2D>& worldStart, bool mapFromRun,
	const MapStep& firstStep);

/** The summary's lines against the truth, and the plans. `scansFitTheMap`:
 * the localised scans lie on the prior map (so a large error against the
 * truth points at the map's frame rather than at a lost filter). */
void printRunReport(
	std::ostream& out, const RunTruth& truth, const std::optional<mrpt::poses::CPose2D>& mapInTruth,
	const std::vector<lvf::metrics::StampedPose>& poses, const std::vector<MapPlan>& plans, const Endpoints& ends,
	bool scansFitTheMap);

}  // namespace lvf::apps
