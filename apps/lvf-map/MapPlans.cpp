#include "MapPlans.h"

#include "GlobalGrids.h"

#include <lvfusion/common/GridOutputs.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/WrittenFiles.h>
#include <lvfusion/planning/PathMetrics.h>
#include <mrpt/core/format.h>


namespace lvf::apps
{
void writeMapPlans(
	lvf::common::StagedOutputFiles& files, const std::string& name, const std::vector<MapPlan>& plans,
	const Endpoints& ends, const lvf::planning::ValueIterationPlanner::TOptions& planner)
{
	std::vector<DrawnPath> drawn;
	for (const auto& p : plans) drawn.push_back({p.plan.path, p.colour});
	lvf::common::OutputFile csv(files.stage(name + "_plans.csv"));
	csv << "map,outcome,length_m,min_clearance_m,sweeps,start_x,start_y,goal_x,goal_y\n";
	for (const auto& p : plans)
	{
		const std::string base = name + "_" + p.name;
		lvf::common::OutputFile pathFile(files.stage(base + "_path.txt"));
		pathFile << "# x[m] y[m], start to goal (empty: no path)\n";
		for (const auto& q : p.plan.path) pathFile << mrpt::format("%.4f %.4f\n", q.x, q.y);
		pathFile.close();
		lvf::common::saveGrid(*p.grid, files.stage(base + "_map.gridmap.gz"));
		mrpt::img::CImage plain;
		p.grid->getAsImage(plain);	// north up
		const std::string picture = files.stage(base + "_map.png");
		lvf::common::requireWritten(plain.saveToFile(picture), picture);

		const lvf::planning::TraversableGrid grown(*p.grid, planner.robotRadius, planner.obstacleBelow);
		csv << mrpt::format(
			"%s,%s,%.3f,%.3f,%zu,%.3f,%.3f,%.3f,%.3f\n", p.name.c_str(),
			p.plan.found() ? "found" : "unreachable", lvf::planning::pathLength(p.plan.path),
			p.plan.found() ? lvf::planning::minimumClearance(p.plan.path, grown) : 0.0, p.plan.sweeps,
			ends.start.x, ends.start.y, ends.goal.x, ends.goal.y);
	}
	// Fig. 14c-d: laser-only map | fused map, over the same area, both paths
	// on each.
	std::vector<const mrpt::maps::COccupancyGridMap2D*> grids;
	std::vector<std::string> labels;
	for (const auto& p : plans)
		grids.push_back(p.grid), labels.push_back(p.name == "laser" ? "laser only" : "laser + vision");
	std::vector<cv::Mat> pictures;
	for (const auto& grid : lvf::common::onCommonExtent(grids))
		pictures.push_back(drawPathsOnGrid(grid, drawn, ends.start, ends.goal));
	csv.close();
	lvf::common::writeImage(files.stage(name + "_paths.png"), lvf::common::sideBySide(pictures, labels));
}

/** Plans on each map. A start or goal the user gave must be usable (an
 * InputError naming where it came from otherwise); the run's own first and
 * last poses may not be (then the summary says why there is no path). */
void planOnEachGrid(
	std::vector<MapPlan>& plans, const Endpoints& ends, const RequestedEndpoints& requested,
	const lvf::planning::ValueIterationPlanner::TOptions& options)
{
	using lvf::planning::PlanOutcome;
	const lvf::planning::ValueIterationPlanner planner(options);
	for (auto& p : plans)
	{
		p.plan = planner.plan(*p.grid, ends.start, ends.goal);
		const auto o = p.plan.outcome;
		auto where = [&](const mrpt::math::TPoint2D& q, bool outside) {
			return mrpt::format(std::abs(q.x) < 1e6 && std::abs(q.y) < 1e6 ? "(%.2f, %.2f) " : "(%g, %g) ", q.x, q.y) +
				(outside ? "is outside the " + p.name + " map"
						 : mrpt::format("is inside an obstacle of the %s map (grown by the robot radius, %.2f m)",
							   p.name.c_str(), options.robotRadius));
		};
		if (requested.start && (o == PlanOutcome::StartOutsideMap || o == PlanOutcome::StartBlocked))
			throw lvf::common::InputError(
				requested.startSource, "", "start " + where(ends.start, o == PlanOutcome::StartOutsideMap));
		if (requested.goal && (o == PlanOutcome::GoalOutsideMap || o == PlanOutcome::GoalBlocked))
			throw lvf::common::InputError(
				requested.goalSource, "", "goal " + where(ends.goal, o == PlanOutcome::GoalOutsideMap));
	}
}

}  // namespace lvf::apps
