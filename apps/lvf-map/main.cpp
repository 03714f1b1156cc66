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
#include "MapPlans.h"
#include "MapRun.h"
#include "ParticleLocalizer.h"
#include "PriorMap.h"
#include "RunReport.h"

#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/GridOutputs.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/ProgressBar.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/metrics/PoseTrajectory.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/system/CTicTac.h>
#include <mrpt/system/filesystem.h>
#include <mrpt/system/string_utils.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <optional>

using lvf::common::InputError;
using mrpt::math::TPoint2D;

namespace
{
const std::string kApp = "lvf-map";
namespace fs = std::filesystem;

TPoint2D parsePoint(const std::string& text, const std::string& option)
{
	const auto comma = text.find(',');
	const auto number = [&](const std::string& part) {
		size_t used = 0;
		const double v = std::stod(part, &used);
		if (mrpt::system::trim(part.substr(used)) != "" || !std::isfinite(v)) throw std::invalid_argument(part);
		return v;
	};
	try
	{
		if (comma != std::string::npos) return {number(text.substr(0, comma)), number(text.substr(comma + 1))};
	}
	catch (const std::exception&)
	{
	}
	throw InputError(option, "", "expected x,y in metres, got '" + text + "'");
}

/** Which input named the start and the goal (for error messages). */
struct EndpointSources
{
	std::string start, goal;
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
	lvf::apps::Endpoints ends;
	EndpointSources sources;
	if (!argWorld.getValue().empty())
	{
		const auto world = lvf::simulation::loadWorldFile(argWorld.getValue());
		start = TPoint2D(world.path.front().x, world.path.front().y);
		sources.start = sources.goal = argWorld.getValue();
		if (!world.target) throw InputError(argWorld.getValue(), "target", "the world has no target to plan to");
		goal = *world.target;
	}
	if (!argStart.getValue().empty()) start = parsePoint(argStart.getValue(), "--start"), sources.start = "--start";
	if (!argGoal.getValue().empty()) goal = parsePoint(argGoal.getValue(), "--goal"), sources.goal = "--goal";

	lvf::common::StagedOutputFiles files(argOutdir.getValue());  // here: a bad folder is told before the work
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
	const lvf::planning::ValueIterationPlanner planner(config.planner);
	std::vector<lvf::apps::MapPlan> plans{{"laser", &grids.laser(), {}, {0, 0, 255}}};
	if (grids.fusedScans()) plans.push_back({"fused", &grids.fused(), {}, {0, 160, 0}});
	for (auto& p : plans)
	{
		p.plan = planner.plan(*p.grid, ends.start, ends.goal);
		using lvf::planning::PlanOutcome;
		const auto o = p.plan.outcome;
		// A start or goal the user gave must be usable; the run's own first
		// and last poses may not be (then the summary says why there is no path).
		auto where = [&](const TPoint2D& q, bool outside) {
			return mrpt::format(std::abs(q.x) < 1e6 && std::abs(q.y) < 1e6 ? "(%.2f, %.2f) " : "(%g, %g) ", q.x, q.y) +
				(outside ? "is outside the " + p.name + " map"
						 : mrpt::format("is inside an obstacle of the %s map (grown by the robot radius, %.2f m)",
										p.name.c_str(), config.planner.robotRadius));
		};
		if (start && (o == PlanOutcome::StartOutsideMap || o == PlanOutcome::StartBlocked))
			throw InputError(sources.start, "", "start " + where(ends.start, o == PlanOutcome::StartOutsideMap));
		if (goal && (o == PlanOutcome::GoalOutsideMap || o == PlanOutcome::GoalBlocked))
			throw InputError(sources.goal, "", "goal " + where(ends.goal, o == PlanOutcome::GoalOutsideMap));
	}

	// Outputs, staged until everything worked.
	lvf::metrics::writePoseFile(files.stage(name + "_poses.txt"), poses);
	if (ownMap)
	{
		auto grid = prior->mapByClass<mrpt::maps::COccupancyGridMap2D>();
		if (grid)
		{
			lvf::common::saveGrid(*grid, files.stage(name + "_prior_map.gridmap.gz"));
			grid->saveAsBitmapFile(files.stage(name + "_prior_map.png"));
		}
	}
	lvf::apps::writeMapPlans(files, name, plans, ends, config.planner);
	files.commit();

	if (quiet) return lvf::common::kExitOk;
	std::cout << mrpt::format(
		"%s: %s: %zu scans (%zu with a fused scan) localised in %.2f s, %zu particles at the end\n"
		"  prior map: %s\n",
		kApp.c_str(), input.c_str(), runLog.steps.size(), runLog.fusedScans, timer.Tac(),
		localizer.particles(), priorText.c_str());
	if (!runLog.fusedScans)
		std::cout << "  no FUSED scans in the input (run lvf-fuse first for the fused map): laser-only map only\n";
	lvf::apps::printRunReport(std::cout, input, poses, plans, ends);
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
