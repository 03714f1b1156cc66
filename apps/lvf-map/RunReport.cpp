#include "RunReport.h"
#include "SerialisedFile.h"

#include <lvfusion/common/RawlogReader.h>
#include <lvfusion/common/Suffixes.h>
#include <lvfusion/metrics/ObstacleGridScore.h>
#include <lvfusion/planning/PathMetrics.h>
#include <mrpt/core/format.h>

#include <cmath>
#include <filesystem>
#include <optional>

namespace lvf::apps
{
namespace
{
namespace fs = std::filesystem;

/** A file lvf-simulate writes beside NAME.rawlog, if it is there (also for
 * lvf-fuse's NAME_fused.rawlog written into the same folder). */
std::optional<std::string> besideInput(const std::string& input, const std::string& suffix)
{
	std::string stem = lvf::common::rawlogName(input);
	for (int attempt = 0; attempt < 2; attempt++)
	{
		const fs::path p = fs::path(input).parent_path() / (stem + suffix);
		if (fs::exists(p)) return p.string();
		if (!lvf::common::stripSuffix(stem, "_fused")) break;
	}
	return std::nullopt;
}
}  // namespace

RunTruth loadRunTruth(const std::string& input)
{
	RunTruth truth;
	truth.posesPath = besideInput(input, "_gt_poses.txt");
	if (truth.posesPath) truth.poses = lvf::metrics::readPoseFile(*truth.posesPath);
	truth.obstaclesPath = besideInput(input, "_obstacles.gridmap.gz");
	if (truth.obstaclesPath) readSerialisedFile(*truth.obstaclesPath, truth.obstacles.emplace(), "ground-truth grid");
	return truth;
}

std::optional<mrpt::poses::CPose2D> mapFrameInTruth(
	const RunTruth& truth, const std::optional<mrpt::poses::CPose2D>& worldStart, bool mapFromRun,
	const MapStep& firstStep)
{
	if (!mapFromRun) return mrpt::poses::CPose2D();
	const auto first = lvf::metrics::poseStampedAt(truth.poses, mrpt::Clock::toDouble(firstStep.laser->timestamp));
	if (!first && !worldStart) return std::nullopt;
	return (first ? first->pose : *worldStart) + (-firstStep.odometry);
}

void printRunReport(
	std::ostream& out, const RunTruth& truth, const std::optional<mrpt::poses::CPose2D>& mapInTruth,
	const std::vector<lvf::metrics::StampedPose>& poses, const std::vector<MapPlan>& plans, const Endpoints& ends,
	bool scansFitTheMap)
{
	if ((truth.posesPath || truth.obstaclesPath) && !mapInTruth)
		out << "  the truth beside the input has no pose at the first scan's time, which would place the map built "
			   "from the run in the truth's frame: not compared\n";
	// Said only where the frames differ (an observations-only log's odometry
	// starts at the truth, up to rounding).
	if (mapInTruth && (std::hypot(mapInTruth->x(), mapInTruth->y()) > 1e-3 || std::abs(mapInTruth->phi()) > 1e-4))
		out << mrpt::format(
			"  the map (in the run's odometry frame) lies at (%.3f m, %.3f m, %.2f deg) in the world's frame, by where "
			"the first scan was taken: the world's start and target and the truth are placed on it\n",
			mapInTruth->x(), mapInTruth->y(), mrpt::RAD2DEG(mapInTruth->phi()));
	if (truth.posesPath && mapInTruth)
	{
		const auto e = lvf::metrics::compareTrajectories(poses, truth.poses, *mapInTruth);
		out << mrpt::format(
			"  localisation against %s (%zu poses): median error %.3f m, %.2f deg (max %.3f m)\n",
			truth.posesPath->c_str(), e.matched, e.medianPosition, mrpt::RAD2DEG(e.medianHeading), e.maxPosition);
		if (scansFitTheMap && e.medianPosition > 0.5)
			out << "  the scans fit the prior map but the poses miss the truth: is the map drawn in the world's "
				   "frame? (a grid lvf-fuse or lvf-map made from a run is in that run's odometry frame)\n";
	}
	std::optional<lvf::planning::TraversableGrid> truthGrid;
	if (truth.obstacles && mapInTruth)
	{
		truthGrid.emplace(*truth.obstacles, 0.0, 0.5);
		for (const auto& p : plans)
		{
			const auto s = lvf::metrics::scoreObstacleGrid(*p.grid, *truth.obstacles, *mapInTruth);
			out << mrpt::format(
				"  %s map against %s: recall %.3f of %zu observed obstacle cells, precision %.3f of %zu occupied\n",
				p.name.c_str(), truth.obstaclesPath->c_str(), s.recall(), s.truthObserved, s.precision(), s.mapOccupied);
		}
	}
	for (const auto& p : plans)
	{
		// Rounded first: a start a hair below zero would print as "-0.00".
		auto shown = [](double v) { return std::abs(v) < 0.005 ? 0.0 : v; };
		out << mrpt::format(
			"  %s map, (%.2f, %.2f) -> (%.2f, %.2f): ", p.name.c_str(), shown(ends.start.x), shown(ends.start.y),
			shown(ends.goal.x), shown(ends.goal.y));
		if (!p.plan.found())
		{
			out << describe(p.plan.outcome);
			// Blocked ends the user gave are errors before this (MapPlans.cpp):
			// these are the run's own first or last pose.
			if (p.plan.outcome == lvf::planning::PlanOutcome::StartBlocked ||
				p.plan.outcome == lvf::planning::PlanOutcome::GoalBlocked)
				out << ", though the robot stood there: [ValueIterationPlanner] robot_radius is wider than the room it "
					   "had (or give --start / --goal)";
			out << "\n";
			continue;
		}
		out << mrpt::format(
			"path %.2f m (%zu value-iteration sweeps)", lvf::planning::pathLength(p.plan.path), p.plan.sweeps);
		if (truthGrid)
		{
			lvf::planning::Path inTruth;
			for (const auto& q : p.plan.path) inTruth.push_back(*mapInTruth + q);
			out << mrpt::format(
				", %.2f m of it through true obstacles, clearance to them %.2f m",
				lvf::planning::lengthThroughObstacles(inTruth, *truthGrid),
				lvf::planning::minimumClearance(inTruth, *truthGrid));
		}
		out << "\n";
	}
}

}  // namespace lvf::apps
