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
#include <lvfusion/common/CountedNoun.h>
#include <lvfusion/common/GridInsertion.h>
#include <lvfusion/common/GridOutputs.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/Medians.h>
#include <lvfusion/common/ProgressBar.h>
#include <lvfusion/common/RawlogReader.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/common/WrittenFiles.h>
#include <lvfusion/metrics/PoseTrajectory.h>
#include <lvfusion/metrics/ScanOnMap.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/system/CTicTac.h>

#include <iostream>
#include <optional>

using mrpt::math::TPoint2D;

namespace
{
const std::string kApp = "lvf-map";

/** The map the particles localise in, and where they start. */
struct Prior
{
	std::shared_ptr<mrpt::maps::CMultiMetricMap> map;
	std::string text;  //!< what it is, for the summary
	mrpt::math::TPose2D initMin, initMax;
	bool onFreeSpace = true;
	std::optional<mrpt::maps::CSimpleMap> ownMap;  //!< built from the run's scans (no map given)
};

/** A warning line if most of the prior map's cells are occupied (a photo
 * given by mistake, an image with the colours inverted): every return then
 * lies "on the map" wherever the particles are, so the lost-robot warning
 * below cannot fire. */
void warnIfMostlyOccupied(const mrpt::maps::CMultiMetricMap& map, const std::string& mapPath)
{
	const auto grid = map.mapByClass<mrpt::maps::COccupancyGridMap2D>();
	if (!grid || grid->getSizeX() == 0 || grid->getSizeY() == 0) return;
	size_t occupied = 0;
	for (unsigned y = 0; y < grid->getSizeY(); y++)
		for (unsigned x = 0; x < grid->getSizeX(); x++) occupied += grid->getCell(x, y) < 0.5f;
	const double share = double(occupied) / (double(grid->getSizeX()) * double(grid->getSizeY()));
	if (share > 0.5)
		std::cerr << mrpt::format(
			"%s: warning: %s: %.0f %% of the prior map is occupied: is it a map (dark = occupied, light = free)? "
			"Scans then match it anywhere\n",
			kApp.c_str(), mapPath.c_str(), 100 * share);
}

/** The map at `mapPath`, or with none one built from the run's scans by
 * MRPT's ICP-SLAM, in the odometry frame: the particles then start round
 * the first odometry pose. */
Prior priorFor(const lvf::apps::LocalizationConfig& config, const std::string& mapPath, const lvf::apps::MapRun& run)
{
	Prior p;
	p.map = std::make_shared<mrpt::maps::CMultiMetricMap>();
	p.map->setListOfMaps(config.maps);
	p.initMin = config.initMin, p.initMax = config.initMax;
	p.onFreeSpace = config.initOnFreeSpace;
	if (!mapPath.empty())
	{
		p.text = lvf::apps::loadPriorMap(mapPath, config.globalMaps.imageResolution, *p.map);
		warnIfMostlyOccupied(*p.map, mapPath);
		return p;
	}
	p.ownMap = lvf::apps::buildMapFromScans(run);
	lvf::apps::loadSimpleMap(*p.ownMap, *p.map);
	p.text = "none given: built from the run's " + lvf::common::counted(run.steps.size(), "laser scan") +
		" by MRPT's ICP-SLAM (" + lvf::common::counted(p.ownMap->size(), "keyframe") + ")";
	const auto& o = run.steps.front().odometry;
	const double xy = config.globalMaps.ownMapInitXY, yaw = mrpt::DEG2RAD(config.globalMaps.ownMapInitYawDeg);
	p.initMin = {o.x() - xy, o.y() - xy, o.phi() - yaw};
	p.initMax = {o.x() + xy, o.y() + xy, o.phi() + yaw};
	p.onFreeSpace = false;
	return p;
}

/** The localised run: a pose per scan, and how well each scan lies on the
 * prior map from there (lvf::metrics::scanShareOnMap; empty without a grid). */
struct Localised
{
	std::vector<lvf::metrics::StampedPose> poses;
	std::vector<double> sharesOnMap;
};

/** Localises every step of the run in turn, adding its scans to `grids`
 * at the estimate. */
Localised localise(
	const lvf::apps::MapRun& run, lvf::apps::ParticleLocalizer& localizer, const mrpt::maps::CMultiMetricMap& prior,
	lvf::apps::GlobalGrids& grids, bool quiet)
{
	Localised out;
	const auto priorGrid = prior.mapByClass<mrpt::maps::COccupancyGridMap2D>();
	lvf::common::ProgressBar progress("localising", run.steps.size());
	for (size_t k = 0; k < run.steps.size(); k++)
	{
		const auto& step = run.steps[k];
		const auto pose = localizer.update(step);
		out.poses.push_back({k, mrpt::Clock::toDouble(step.laser->timestamp), pose});
		if (priorGrid)
			out.sharesOnMap.push_back(lvf::metrics::scanShareOnMap(
				*step.laser, pose, *priorGrid, priorGrid->insertionOptions.maxDistanceInsertion));
		if (!grids.add(*step.laser, step.fused.get(), pose))
			std::cerr << mrpt::format(
				"%s: warning: scan %zu: its localised pose (%.3g, %.3g), or its sensor pose on the robot, is not finite or "
				"lies more than %.0f m outside the maps: left out of them\n",
				kApp.c_str(), k, pose.x(), pose.y(), lvf::common::kMaxGridGrowth);
		if (!quiet) progress.update(k + 1);
	}
	grids.finish();
	return out;
}

/** How the localised scans lie on the prior map: the median share of their
 * returns on it, how many have under half, and the first of those. */
struct ScansOnMap
{
	double median = 0;
	size_t under = 0, total = 0;
	std::ptrdiff_t firstUnder = -1;
	/** Most scans lie off the map: the filter has most likely lost the
	 * robot, and everything after that is built at wrong poses. */
	bool lost() const { return 2 * under > total; }
};

std::optional<ScansOnMap> summariseScansOnMap(const std::vector<double>& shares)
{
	if (shares.empty()) return std::nullopt;
	ScansOnMap s;
	s.median = lvf::common::upperMedian(shares, 0.0);
	s.total = shares.size();
	for (size_t k = 0; k < shares.size(); k++)
		if (shares[k] < 0.5)
		{
			if (s.under++ == 0) s.firstUnder = static_cast<std::ptrdiff_t>(k);
		}
	return s;
}

int run(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"lvf-map: localise a run with MRPT's particle filter (CMonteCarloLocalization2D) against a "
		"prior laser map, accumulate its laser scans and lvf-fuse's fused scans into two global "
		"occupancy grids, and plan a path on each by value iteration (paper §7, Fig. 14).",
		' ', "0.1.0");
	// Not TCLAP-required: --dump-config needs no run.
	TCLAP::ValueArg<std::string> argInput("i", "input", "Input rawlog, either MRPT layout (lvf-fuse's NAME_fused.rawlog for the fused map); required unless --dump-config", false, "", "RUN.rawlog", cmd);
	TCLAP::ValueArg<std::string> argMap("m", "map", "Prior laser map to localise against: .gridmap(.gz), .simplemap(.gz) or an image (default: map_file of the config, else built from the run's scans)", false, "", "PRIOR", cmd);
	TCLAP::ValueArg<std::string> argConfig("c", "config", "Configuration: MRPT pf-localization INI sections plus [GlobalMaps] and [ValueIterationPlanner] (--dump-config lists them all)", false, "", "FILE.ini", cmd);
	TCLAP::ValueArg<std::string> argOutdir("o", "outdir", "Output folder (default: lvf-out)", false, "lvf-out", "DIR", cmd);
	TCLAP::ValueArg<std::string> argStart("", "start", "Start of the planned path (default: the world's first pose, else the first localised pose)", false, "", "X,Y", cmd);
	TCLAP::ValueArg<std::string> argGoal("", "goal", "Goal of the planned path (default: the world's target, else the last localised pose)", false, "", "X,Y", cmd);
	TCLAP::ValueArg<std::string> argWorld("w", "world", "World file giving start (first path pose) and goal (target), in the world's frame (moved onto a map built from the run by where its first scan was taken)", false, "", "W.yaml", cmd);
	// Read wider than unsigned: TCLAP would wrap "-1" to 4294967295.
	TCLAP::ValueArg<long long> argSeed("", "seed", "Seed of the particle filter's random numbers, 0 to 4294967295 (default 1)", false, 1, "N", cmd);
	TCLAP::SwitchArg argDumpConfig("", "dump-config", "Print the complete configuration (defaults overridden by --config) and exit", cmd);
	TCLAP::SwitchArg argQuiet("q", "quiet", "Print nothing but errors and warnings", cmd);
	if (!lvf::common::parseCommandLine(cmd, argc, argv)) return lvf::common::kExitOk;

	const auto config = lvf::apps::LocalizationConfig::load(argConfig.getValue());
	if (argDumpConfig.getValue())
	{
		std::cout << config.dump();
		return lvf::common::kExitOk;
	}
	if (!argInput.isSet())
		throw lvf::common::InputError("command line", "", "missing required argument(s) --input (see --help)");
	const bool quiet = argQuiet.getValue();
	mrpt::system::CTicTac timer;
	const std::string input = argInput.getValue();
	const std::string name = lvf::common::rawlogName(input);

	if (argSeed.getValue() < 0 || argSeed.getValue() > 4294967295LL)
		throw lvf::common::InputError("--seed", "", "must be in [0, 4294967295]");
	// Where the plan starts and ends, checked before any work.
	auto requested = lvf::apps::requestedEndpoints(argWorld.getValue(), argStart.getValue(), argGoal.getValue());
	lvf::common::rejectRawlogNamedFolder(argOutdir.getValue(), "--outdir", "the maps and plans are written inside it");
	lvf::common::StagedOutputFiles files(argOutdir.getValue());  // here: a bad folder is told before the work
	const auto runLog = lvf::apps::loadMapRun(input, config.obsOnlyOdometry);
	const auto truth = lvf::apps::loadRunTruth(input);

	// The prior map, and where the particles start.
	const auto prior = priorFor(config, argMap.getValue().empty() ? config.mapFile : argMap.getValue(), runLog);
	const auto mapInTruth =
		lvf::apps::mapFrameInTruth(truth, requested.worldStart, prior.ownMap.has_value(), runLog.steps.front());
	if (mapInTruth) lvf::apps::placeWorldEndpointsOnMap(requested, *mapInTruth);

	// 1-2. Localise every scan; accumulate both grids at the estimates.
	mrpt::random::getRandomGenerator().randomize(static_cast<unsigned>(argSeed.getValue()));
	lvf::apps::ParticleLocalizer localizer(config, prior.map, prior.initMin, prior.initMax, prior.onFreeSpace);
	lvf::apps::GlobalGrids grids(config.globalMaps.resolution, config.globalMaps.visualMinHits);
	const auto localised = localise(runLog, localizer, *prior.map, grids, quiet);
	const auto& poses = localised.poses;

	// 3. Plan on each grid.
	lvf::apps::Endpoints ends;
	ends.start = requested.start.value_or(TPoint2D(poses.front().pose.x(), poses.front().pose.y()));
	ends.goal = requested.goal.value_or(TPoint2D(poses.back().pose.x(), poses.back().pose.y()));
	std::vector<lvf::apps::MapPlan> plans{{"laser", &grids.laser(), {}, {0, 0, 255}}};
	if (grids.fusedScans()) plans.push_back({"fused", &grids.fused(), {}, {0, 160, 0}});
	lvf::apps::planOnEachGrid(plans, ends, requested, config.planner);

	// Outputs, staged until everything worked.
	lvf::metrics::writePoseFile(files.stage(name + "_poses.txt"), poses);
	if (prior.ownMap)
	{
		auto grid = prior.map->mapByClass<mrpt::maps::COccupancyGridMap2D>();
		if (grid)
		{
			lvf::common::saveGrid(*grid, files.stage(name + "_prior_map.gridmap.gz"));
			const std::string picture = files.stage(name + "_prior_map.png");
			lvf::common::requireWritten(grid->saveAsBitmapFile(picture), picture);
		}
	}
	lvf::apps::writeMapPlans(files, name, plans, ends, config.planner);
	files.commit();

	// Told also when quiet: what was built after the filter lost the robot is wrong.
	const auto onMap = summariseScansOnMap(localised.sharesOnMap);
	if (onMap && onMap->lost())
		std::cerr << mrpt::format(
			"%s: warning: most localised scans lie off the prior map (%zu of %zu, the first at scan %td): the filter "
			"has probably lost the robot; check the prior map and the initial box, or widen [DummyOdometryParams]\n",
			kApp.c_str(), onMap->under, onMap->total, onMap->firstUnder);
	if (quiet) return lvf::common::kExitOk;
	std::cout << mrpt::format(
		"%s: %s: %s (%zu with a fused scan) localised in %.2f s, %zu particles at the end\n"
		"  prior map: %s\n",
		kApp.c_str(), input.c_str(), lvf::common::counted(runLog.steps.size(), "scan").c_str(), runLog.fusedScans, timer.Tac(),
		localizer.particles(), prior.text.c_str());
	if (!runLog.fusedScans)
		std::cout << "  no FUSED scans in the input (run lvf-fuse first for the fused map): laser-only map only\n";
	if (onMap)
		std::cout << mrpt::format(
			"  localised scans on the prior map: median share of their returns %.2f, %zu of %zu scans under half\n",
			onMap->median, onMap->under, onMap->total);
	lvf::apps::printRunReport(std::cout, truth, mapInTruth, poses, plans, ends, onMap && onMap->median >= 0.9);
	std::cout << "  wrote " << name << "_poses.txt, " << name << (grids.fusedScans() ? "_{laser,fused}" : "_laser")
			  << "_{map.gridmap.gz,map.png,path.txt}, " << name << "_paths.png, " << name << "_plans.csv"
			  << (prior.ownMap ? ", " + name + "_prior_map.{gridmap.gz,png}" : "") << " in " << files.outputDir() << "\n";
	return lvf::common::kExitOk;
}

}  // namespace

int main(int argc, char** argv)
{
	return lvf::common::runApp(kApp, [&] { return run(argc, argv); });
}
