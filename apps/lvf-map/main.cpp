// lvf-map: global maps from a whole run (paper §7, Fig. 14). See README.md.
//
//  1. localise every scan with MRPT's particle filter against a prior laser
//     map (given, or built from the run's scans by MRPT's ICP-SLAM);
//  2. accumulate the laser scans, and lvf-fuse's FUSED scans, at the
//     localised poses into two global occupancy grids;
//  3. plan by value iteration on each grid from a start to a goal, and draw
//     both paths on both maps.

#include "GlobalGrids.h"
#include "LocalizationConfig.h"
#include "MapRun.h"
#include "ParticleLocalizer.h"
#include "PriorMap.h"

#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/ProgressBar.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/metrics/ObstacleGridScore.h>
#include <lvfusion/metrics/PoseTrajectory.h>
#include <lvfusion/planning/PathMetrics.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/CTicTac.h>
#include <mrpt/system/filesystem.h>
#include <opencv2/imgcodecs.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <regex>

using lvf::common::InputError;
using mrpt::math::TPoint2D;

namespace
{
const std::string kApp = "lvf-map";
namespace fs = std::filesystem;

TPoint2D parsePoint(const std::string& text, const std::string& option)
{
	static const std::regex xy(R"(\s*([-+0-9.eE]+)\s*,\s*([-+0-9.eE]+)\s*)");
	std::smatch m;
	try
	{
		if (std::regex_match(text, m, xy)) return {std::stod(m[1]), std::stod(m[2])};
	}
	catch (const std::exception&)
	{
	}
	throw InputError(option, "", "expected x,y in metres, got '" + text + "'");
}

/** Start and goal, and which input named them (for error messages). */
struct Endpoints
{
	TPoint2D start, goal;
	std::string startSource, goalSource;
};

/** A file lvf-simulate writes beside NAME.rawlog, if it is there (also for
 * lvf-fuse's NAME_fused.rawlog written into the same folder). */
std::optional<std::string> besideInput(const std::string& input, const std::string& suffix)
{
	std::string stem = fs::path(input).stem().string();
	for (int attempt = 0; attempt < 2; attempt++)
	{
		const fs::path p = fs::path(input).parent_path() / (stem + suffix);
		if (fs::exists(p)) return p.string();
		const std::string fused = "_fused";
		if (stem.size() <= fused.size() || stem.compare(stem.size() - fused.size(), fused.size(), fused)) break;
		stem.resize(stem.size() - fused.size());
	}
	return std::nullopt;
}

struct PlanOnMap
{
	std::string name;  //!< laser / fused
	const mrpt::maps::COccupancyGridMap2D* grid;
	lvf::planning::ValueIterationPlanner::Result plan;
	cv::Scalar colour;
};

int run(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"lvf-map: localise a run with MRPT's particle filter (CMonteCarloLocalization2D) against a "
		"prior laser map, accumulate its laser scans and lvf-fuse's fused scans into two global "
		"occupancy grids, and plan a path on each by value iteration (paper §7, Fig. 14).",
		' ', "0.1.0");
	TCLAP::ValueArg<std::string> argInput("i", "input", "Input rawlog, either MRPT layout (lvf-fuse's NAME_fused.rawlog for the fused map)", true, "", "RUN.rawlog", cmd);
	TCLAP::ValueArg<std::string> argMap("m", "map", "Prior laser map to localise against: .gridmap(.gz), .simplemap(.gz) or an image (default: map_file of the config, else built from the run's scans)", false, "", "PRIOR", cmd);
	TCLAP::ValueArg<std::string> argConfig("c", "config", "Configuration: MRPT pf-localization INI sections plus [GlobalMaps] and [ValueIterationPlanner] (--dump-config lists them all)", false, "", "FILE.ini", cmd);
	TCLAP::ValueArg<std::string> argOutdir("o", "outdir", "Output folder (default: lvf-out)", false, "lvf-out", "DIR", cmd);
	TCLAP::ValueArg<std::string> argStart("", "start", "Start of the planned path (default: the world's first pose, else the first localised pose)", false, "", "X,Y", cmd);
	TCLAP::ValueArg<std::string> argGoal("", "goal", "Goal of the planned path (default: the world's target, else the last localised pose)", false, "", "X,Y", cmd);
	TCLAP::ValueArg<std::string> argWorld("w", "world", "World file giving start (first path pose) and goal (target)", false, "", "W.yaml", cmd);
	TCLAP::ValueArg<unsigned> argSeed("", "seed", "Seed of the particle filter's random numbers (default 1)", false, 1, "N", cmd);
	TCLAP::SwitchArg argDumpConfig("", "dump-config", "Print the complete configuration (defaults overridden by --config) and exit", cmd);
	TCLAP::SwitchArg argQuiet("q", "quiet", "Print nothing but errors and warnings", cmd);
	if (!lvf::common::parseCommandLine(cmd, argc, argv)) return lvf::common::kExitOk;

	const auto config = lvf::apps::LocalizationConfig::load(argConfig.getValue());
	if (argDumpConfig.getValue())
	{
		std::cout << config.dump();
		return lvf::common::kExitOk;
	}
	const bool quiet = argQuiet.getValue();
	mrpt::system::CTicTac timer;
	const std::string input = argInput.getValue();
	const std::string name = fs::path(input).stem().string();

	// Where the plan starts and ends, checked before any work.
	std::optional<TPoint2D> start, goal;
	Endpoints ends;
	if (!argWorld.getValue().empty())
	{
		const auto world = lvf::simulation::loadWorldFile(argWorld.getValue());
		start = TPoint2D(world.path.front().x, world.path.front().y);
		ends.startSource = ends.goalSource = argWorld.getValue();
		if (!world.target) throw InputError(argWorld.getValue(), "target", "the world has no target to plan to");
		goal = *world.target;
	}
	if (!argStart.getValue().empty()) start = parsePoint(argStart.getValue(), "--start"), ends.startSource = "--start";
	if (!argGoal.getValue().empty()) goal = parsePoint(argGoal.getValue(), "--goal"), ends.goalSource = "--goal";

	const auto runLog = lvf::apps::loadMapRun(input, config.obsOnlyOdometry);

	// The prior map, and where the particles start.
	auto prior = std::make_shared<mrpt::maps::CMultiMetricMap>();
	prior->setListOfMaps(config.maps);
	const std::string mapPath = argMap.getValue().empty() ? config.mapFile : argMap.getValue();
	std::string priorText;
	mrpt::math::TPose2D initMin = config.initMin, initMax = config.initMax;
	bool onFreeSpace = config.initOnFreeSpace;
	std::optional<mrpt::maps::CSimpleMap> ownMap;
	if (!mapPath.empty())
		priorText = lvf::apps::loadPriorMap(mapPath, config.globalMaps.imageResolution, *prior);
	else
	{
		ownMap = lvf::apps::buildMapFromScans(runLog);
		prior->loadFromProbabilisticPosesAndObservations(*ownMap);
		priorText = mrpt::format(
			"none given: built from the run's %zu laser scans by MRPT's ICP-SLAM (%zu keyframes)",
			runLog.steps.size(), ownMap->size());
		// That map is in the odometry frame: start at the first odometry pose.
		const auto& o = runLog.steps.front().odometry;
		const double xy = config.globalMaps.ownMapInitXY, yaw = mrpt::DEG2RAD(config.globalMaps.ownMapInitYawDeg);
		initMin = {o.x() - xy, o.y() - xy, o.phi() - yaw};
		initMax = {o.x() + xy, o.y() + xy, o.phi() + yaw};
		onFreeSpace = false;
	}

	// 1-2. Localise every scan; accumulate both grids at the estimates.
	mrpt::random::getRandomGenerator().randomize(argSeed.getValue());
	lvf::apps::ParticleLocalizer localizer(config, prior, initMin, initMax, onFreeSpace);
	lvf::apps::GlobalGrids grids(config.globalMaps.resolution, config.globalMaps.visualMinHits);
	std::vector<lvf::metrics::StampedPose> poses;
	lvf::common::ProgressBar progress("localising", runLog.steps.size());
	for (size_t k = 0; k < runLog.steps.size(); k++)
	{
		const auto& step = runLog.steps[k];
		const auto pose = localizer.update(step);
		poses.push_back({k, mrpt::Clock::toDouble(step.laser->timestamp), pose});
		grids.add(*step.laser, step.fused.get(), pose);
		if (!quiet) progress.update(k + 1);
	}
	grids.finish();

	// 3. Plan on each grid.
	ends.start = start.value_or(TPoint2D(poses.front().pose.x(), poses.front().pose.y()));
	ends.goal = goal.value_or(TPoint2D(poses.back().pose.x(), poses.back().pose.y()));
	if (ends.startSource.empty()) ends.startSource = "the first localised pose";
	if (ends.goalSource.empty()) ends.goalSource = "the last localised pose";
	const lvf::planning::ValueIterationPlanner planner(config.planner);
	std::vector<PlanOnMap> plans{{"laser", &grids.laser(), {}, {0, 0, 255}}};
	if (grids.fusedScans()) plans.push_back({"fused", &grids.fused(), {}, {0, 160, 0}});
	for (auto& p : plans)
	{
		p.plan = planner.plan(*p.grid, ends.start, ends.goal);
		using lvf::planning::PlanOutcome;
		const auto o = p.plan.outcome;
		// A start or goal the user gave must be usable; the run's own first
		// and last poses may not be (then the summary says why there is no path).
		auto where = [&](const TPoint2D& q, bool outside) {
			return mrpt::format("(%.2f, %.2f) ", q.x, q.y) +
				(outside ? "is outside the " + p.name + " map"
						 : mrpt::format("is inside an obstacle of the %s map (grown by the robot radius, %.2f m)",
										p.name.c_str(), config.planner.robotRadius));
		};
		if (start && (o == PlanOutcome::StartOutsideMap || o == PlanOutcome::StartBlocked))
			throw InputError(ends.startSource, "", "start " + where(ends.start, o == PlanOutcome::StartOutsideMap));
		if (goal && (o == PlanOutcome::GoalOutsideMap || o == PlanOutcome::GoalBlocked))
			throw InputError(ends.goalSource, "", "goal " + where(ends.goal, o == PlanOutcome::GoalOutsideMap));
	}

	// Outputs, staged until everything worked.
	lvf::common::StagedOutputFiles files(argOutdir.getValue());
	lvf::metrics::writePoseFile(files.stage(name + "_poses.txt"), poses);
	std::vector<lvf::apps::DrawnPath> drawn;
	for (const auto& p : plans) drawn.push_back({p.plan.path, p.colour});
	std::vector<cv::Mat3b> panels;
	for (const auto& p : plans)
	{
		std::ofstream pathFile(files.stage(name + "_" + p.name + "_path.txt"));
		pathFile << "# x[m] y[m], start to goal (empty: no path)\n";
		for (const auto& q : p.plan.path) pathFile << mrpt::format("%.4f %.4f\n", q.x, q.y);
		lvf::apps::saveGrid(*p.grid, files.stage(name + "_" + p.name + "_map.gridmap.gz"));
		mrpt::img::CImage plain;
		p.grid->getAsImage(plain);	// north up
		plain.saveToFile(files.stage(name + "_" + p.name + "_map.png"));
		panels.push_back(lvf::apps::drawPathsOnGrid(*p.grid, drawn, ends.start, ends.goal));
	}
	if (ownMap)
	{
		auto grid = prior->mapByClass<mrpt::maps::COccupancyGridMap2D>();
		if (grid)
		{
			lvf::apps::saveGrid(*grid, files.stage(name + "_prior_map.gridmap.gz"));
			grid->saveAsBitmapFile(files.stage(name + "_prior_map.png"));
		}
	}
	{
		// Fig. 14c-d: laser-only map | fused map, both paths on each.
		int rows = 0;
		for (const auto& p : panels) rows = std::max(rows, p.rows);
		for (auto& p : panels)
			cv::copyMakeBorder(p, p, 0, rows - p.rows, 0, 10, cv::BORDER_CONSTANT, cv::Scalar::all(255));
		cv::Mat sideBySide;
		cv::hconcat(panels, sideBySide);
		cv::imwrite(files.stage(name + "_paths.png"), sideBySide);
	}
	std::ofstream csv(files.stage(name + "_plans.csv"));
	csv << "map,outcome,length_m,min_clearance_m,sweeps,start_x,start_y,goal_x,goal_y\n";
	for (const auto& p : plans)
	{
		const lvf::planning::TraversableGrid own(*p.grid, config.planner.robotRadius, config.planner.obstacleBelow);
		csv << mrpt::format(
			"%s,%s,%.3f,%.3f,%zu,%.3f,%.3f,%.3f,%.3f\n", p.name.c_str(),
			p.plan.found() ? "found" : "unreachable", lvf::planning::pathLength(p.plan.path),
			p.plan.found() ? lvf::planning::minimumClearance(p.plan.path, own) : 0.0, p.plan.sweeps,
			ends.start.x, ends.start.y, ends.goal.x, ends.goal.y);
	}
	csv.close();
	files.commit();

	if (quiet) return lvf::common::kExitOk;
	std::cout << mrpt::format(
		"%s: %s: %zu scans (%zu with a fused scan) localised in %.2f s, %zu particles at the end\n"
		"  prior map: %s\n",
		kApp.c_str(), input.c_str(), runLog.steps.size(), runLog.fusedScans, timer.Tac(),
		localizer.particles(), priorText.c_str());
	if (!runLog.fusedScans)
		std::cout << "  no FUSED scans in the input (run lvf-fuse first for the fused map): laser-only map only\n";
	// Ground truth beside a simulated run: how good the estimate and maps are.
	if (const auto gtPath = besideInput(input, "_gt_poses.txt"))
	{
		const auto e = lvf::metrics::compareTrajectories(poses, lvf::metrics::readPoseFile(*gtPath));
		std::cout << mrpt::format(
			"  localisation against %s (%zu poses): median error %.3f m, %.2f deg (max %.3f m)\n",
			gtPath->c_str(), e.matched, e.medianPosition, mrpt::RAD2DEG(e.medianHeading), e.maxPosition);
	}
	std::optional<lvf::planning::TraversableGrid> truthGrid;
	if (const auto obstaclesPath = besideInput(input, "_obstacles.gridmap.gz"))
	{
		mrpt::maps::COccupancyGridMap2D truth;
		mrpt::io::CFileGZInputStream in(*obstaclesPath);
		mrpt::serialization::archiveFrom(in) >> truth;
		truthGrid.emplace(truth, 0.0, 0.5);
		for (const auto& p : plans)
		{
			const auto s = lvf::metrics::scoreObstacleGrid(*p.grid, truth);
			std::cout << mrpt::format(
				"  %s map against %s: recall %.3f of %zu observed obstacle cells, precision %.3f of %zu occupied\n",
				p.name.c_str(), obstaclesPath->c_str(), s.recall(), s.truthObserved, s.precision(), s.mapOccupied);
		}
	}
	for (const auto& p : plans)
	{
		std::cout << mrpt::format(
			"  %s map, (%.2f, %.2f) -> (%.2f, %.2f): ", p.name.c_str(), ends.start.x, ends.start.y, ends.goal.x,
			ends.goal.y);
		if (!p.plan.found())
		{
			std::cout << describe(p.plan.outcome) << "\n";
			continue;
		}
		std::cout << mrpt::format(
			"path %.2f m (%zu value-iteration sweeps)", lvf::planning::pathLength(p.plan.path), p.plan.sweeps);
		if (truthGrid)
			std::cout << mrpt::format(
				", %.2f m of it through true obstacles, clearance to them %.2f m",
				lvf::planning::lengthThroughObstacles(p.plan.path, *truthGrid),
				lvf::planning::minimumClearance(p.plan.path, *truthGrid));
		std::cout << "\n";
	}
	std::cout << "  wrote " << name << "_poses.txt, " << name << "_{laser" << (grids.fusedScans() ? ",fused" : "")
			  << "}_{map.gridmap.gz,map.png,path.txt}, " << name << "_paths.png, " << name << "_plans.csv"
			  << (ownMap ? ", " + name + "_prior_map.{gridmap.gz,png}" : "") << " in " << files.outputDir() << "\n";
	return lvf::common::kExitOk;
}

}  // namespace

int main(int argc, char** argv)
{
	return lvf::common::runApp(kApp, [&] { return run(argc, argv); });
}
