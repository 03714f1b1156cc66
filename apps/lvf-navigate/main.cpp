// lvf-navigate: closed-loop navigation in simulated worlds (issue 4). See
// README.md and libs/navigation/include/lvfusion/navigation/NavigationRun.h.

#include "BatchTable.h"
#include "TrajectoryImage.h"

#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/vfh/CHolonomicVFH.h>
#include <lvfusion/common/RawlogWriter.h>
#include <lvfusion/common/ShippedFiles.h>
#include <lvfusion/common/SignalCleanup.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/common/ThreadsOption.h>
#include <lvfusion/common/WrittenFiles.h>
#include <lvfusion/metrics/PoseTrajectory.h>
#include <lvfusion/navigation/HolonomicMethods.h>
#include <lvfusion/navigation/NavigationRun.h>
#include <lvfusion/navigation/NavigatorConfig.h>
#include <lvfusion/navigation/RandomScenario.h>
#include <lvfusion/plugin/registerAllClasses.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/string_utils.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>

using lvf::common::InputError;
namespace nav = lvf::navigation;

namespace
{
const std::string kApp = "lvf-navigate";
const std::string kDefaultConfig =
	lvf::common::shippedFile("config/navigate.ini", std::string(LVF_SHARE_DIR) + "/config/navigate.ini");
const std::string kDefaultWorld =
	lvf::common::shippedFile("worlds/box_room.yaml", std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml");
const std::string kSensorsSection = "CStereoLaserSimulator", kFusionSection = "CLaserStereoFusion";

/** Loads `options` from the sections of `file` it owns (the ones its
 * saveToConfigFile writes): the simulator's and the fusion's loaders refuse
 * sections they do not know, and a navigation INI has MRPT's too. */
template <class Options>
void loadOwnSections(Options& options, const std::string& section, const mrpt::config::CConfigFileBase& file, const std::string& path)
{
	mrpt::config::CConfigFileMemory defaults, own;
	options.saveToConfigFile(defaults, section);
	std::vector<std::string> sections, keys;
	defaults.getAllSections(sections);
	for (const auto& s : sections)
	{
		file.getAllKeys(s, keys);
		for (const auto& k : keys) own.write(s, k, file.read_string(s, k, ""));
	}
	try
	{
		options.loadFromConfigFile(own, section);
	}
	catch (const InputError& e)	 // it names "<memory>": name the file instead
	{
		const std::string what = e.what(), memory = "<memory>: ";
		throw InputError(path, "", what.rfind(memory, 0) == 0 ? what.substr(memory.size()) : what);
	}
}

/** --dump-config: everything a run uses, as one INI that reads back as --config. */
std::string dumpConfig(const nav::NavigationSetup& setup)
{
	mrpt::config::CConfigFileMemory out(nav::completeNavigatorConfig(setup.navigatorConfig, setup.method));
	setup.loop.saveToConfigFile(out, "NavigationLoop");
	setup.sensors.saveToConfigFile(out, kSensorsSection);
	setup.fusion.saveToConfigFile(out, kFusionSection);
	return "# lvf-navigate --dump-config: the complete configuration of a run.\n"
		   "# [NavigationLoop] is lvf-navigate's (units in the comments); [" + kSensorsSection + "] the\n"
		   "# simulator's, [" + kFusionSection + "] the fusion's; every other section is MRPT's\n"
		   "# reactive navigator's, as MRPT 2.5 writes it (the robot shape is replaced at run time\n"
		   "# by the world's cylinder). Use it as --config.\n" +
		out.getContent();
}

/** "a, b,c" -> {"a", "b", "c"}: a comma-separated option's items, trimmed. */
std::vector<std::string> splitList(const std::string& text)
{
	std::vector<std::string> items;
	mrpt::system::tokenize(text, ",", items);
	for (auto& item : items) item = mrpt::system::trim(item);
	return items;
}

/** "x,y[,deg]" with exactly `count` numbers; "nan" parses (a NaN pose is a
 * scenario the run reports, not a typo). */
std::vector<double> parseNumbers(const std::string& text, size_t count, const std::string& source)
{
	const auto items = splitList(text);
	std::vector<double> v;
	for (const auto& item : items)
	{
		char* end = nullptr;
		const std::string t = mrpt::system::trim(item);
		v.push_back(std::strtod(t.c_str(), &end));
		if (t.empty() || *end != '\0') throw InputError(source, "", "'" + t + "' is not a number");
	}
	if (v.size() != count) throw InputError(source, "", mrpt::format("expected %zu comma-separated numbers, got '%s'", count, text.c_str()));
	return v;
}

std::string readText(const std::string& path)
{
	lvf::common::openIniFile(path);	 // the line check: a typo is an error, not a skipped line
	std::ifstream in(path);
	std::stringstream s;
	s << in.rdbuf();
	return s.str();
}

/** A private folder for MRPT's PTG look-up tables during a run or batch. */
class TemporaryFolder
{
   public:
	TemporaryFolder()
	{
		std::string pattern = (std::filesystem::temp_directory_path() / "lvf-navigate-XXXXXX").string();
		if (!mkdtemp(pattern.data())) throw std::runtime_error("cannot create a temporary folder");
		m_path = pattern;
		lvf::common::removeOnSignal(m_path);
	}
	~TemporaryFolder()
	{
		std::error_code ignored;
		std::filesystem::remove_all(m_path, ignored);
		lvf::common::keepOnSignal(m_path);
	}
	const std::string& path() const { return m_path; }

   private:
	std::string m_path;
};

/** NAME_trajectory.png, the path over the true obstacles, and NAME_poses.txt,
 * the true pose of every control cycle stamped as the run's rawlog is. */
void writeTrajectory(
	const nav::NavigationScenario& scenario, const nav::NavigationRun& run, const nav::NavigationSetup& setup,
	lvf::common::StagedOutputFiles& files, const std::string& name)
{
	lvf::apps::writeTrajectoryImage(scenario, run, setup.loop.targetTolerance, files.stage(name + "_trajectory.png"));
	const auto& trajectory = run.metrics.trajectory;
	std::vector<lvf::metrics::StampedPose> poses;
	for (size_t k = 0; k < trajectory.size(); k++)
		poses.push_back({k, setup.sensors.startTime + double(k) * setup.loop.controlPeriod,
			mrpt::poses::CPose2D(trajectory[k])});
	lvf::metrics::writePoseFile(files.stage(name + "_poses.txt"), poses);
}

int runSingle(const nav::NavigationScenario& scenario, nav::NavigationSetup setup, const std::string& outdir, bool quiet)
{
	lvf::common::StagedOutputFiles files(outdir);
	const std::string name = scenario.world.name;
	const std::string navlog = name + "_navlog";
	TemporaryFolder ptgCache;
	setup.ptgCacheDir = ptgCache.path();
	setup.navigatorLogDir = files.stage(navlog + "/");
	std::filesystem::create_directories(setup.navigatorLogDir);
	const std::string runLog = name + "_run.rawlog";
	lvf::common::RawlogWriter rawlog(files.stage(runLog), lvf::common::RawlogFormat::ActionsSensoryFrames);
	size_t framesSensed = 0;
	setup.onSensing = [&](const auto& frame, const auto& result) {
		lvf::common::RawlogFrame f;
		f.timestamp = frame.timestamp;
		f.odometry = frame.odometry;
		f.observations.push_back(frame.scan);
		if (frame.stereo) f.observations.push_back(frame.stereo);
		f.observations.push_back(result.fused);
		rawlog.append(f);
		framesSensed++;
	};
	const auto run = nav::runNavigation(scenario, setup);
	rawlog.close();
	const auto& m = run.metrics;
	const std::string line = mrpt::format(
		"%s: %s %s %s: %s", kApp.c_str(), name.c_str(), setup.method.c_str(),
		nav::sensingName(setup.sensing), m.summary().c_str());
	// A scenario that could not be run (a NaN pose, a start in collision)
	// sensed nothing: its metrics say why, and no empty log is left.
	std::vector<std::string> written;
	if (framesSensed > 0)
		written = {"run.rawlog"};
	else
	{
		files.withdraw(runLog);
		files.withdraw(navlog);
	}
	if (!m.trajectory.empty())
	{
		writeTrajectory(scenario, run, setup, files, name);
		written.insert(written.begin(), {"trajectory.png", "poses.txt"});
	}
	lvf::common::writeTextFile(files.stage(name + "_metrics.txt"), line + "\n" + m.detail + "\n");
	written.push_back("metrics.txt");
	files.commit();
	std::cout << line << "\n";
	if (!quiet)
	{
		std::string list;
		for (const auto& w : written) list += (list.empty() ? "" : ",") + w;
		std::cout << "  " << m.detail << "\n  wrote " << name << (written.size() > 1 ? "_{" + list + "}" : "_" + list)
				  << (framesSensed > 0 ? ", " + navlog + "/" : std::string()) << " in " << files.outputDir() << "\n";
	}
	return nav::outcomeExitStatus(m.outcome);
}

int runBatch(
	int count, uint32_t firstSeed, const std::vector<nav::RoomKind>& kinds,
	const std::vector<std::string>& methods, const std::vector<nav::Sensing>& sensings,
	nav::NavigationSetup setup, const std::string& outdir, bool quiet)
{
	lvf::common::StagedOutputFiles files(outdir);
	TemporaryFolder ptgCache;
	setup.ptgCacheDir = ptgCache.path();
	std::vector<lvf::apps::BatchRow> rows;
	for (const auto kind : kinds)
		for (int i = 0; i < count; i++)
		{
			const auto scenario = nav::randomScenario(firstSeed + uint32_t(i), kind);
			for (const auto& method : methods)
				for (const auto sensing : sensings)
				{
					setup.method = method;
					setup.sensing = sensing;
					auto& row = rows.emplace_back();
					row = {nav::roomKindName(kind), scenario.world.name, method, nav::sensingName(sensing), nav::runNavigation(scenario, setup).metrics};
					if (!quiet)
						std::cout << mrpt::format("%s %s %s: %s\n", row.world.c_str(), method.c_str(), row.sensing.c_str(), row.metrics.summary().c_str()) << std::flush;
				}
		}
	lvf::apps::writeBatchCsv(rows, files.stage("batch.csv"));
	std::ostringstream table;
	lvf::apps::printBatchTable(rows, table);
	lvf::common::writeTextFile(files.stage("batch.txt"), table.str());
	files.commit();
	std::cout << table.str() << "  wrote batch.csv, batch.txt in " << files.outputDir() << "\n";
	return lvf::common::kExitOk;
}

/** An option's value where the command line gives it. */
template <typename T>
std::optional<T> ifGiven(TCLAP::ValueArg<T>& option)
{
	return option.isSet() ? std::optional<T>(option.getValue()) : std::nullopt;
}

/** The loop's, the navigator's, the simulator's and the fusion's
 * configuration and the holonomic method: --config, with the sensors' and
 * the fusion's own files (if given) and --method, --timeout over it. */
nav::NavigationSetup loadSetup(
	const std::string& config, const std::string& sensors, const std::string& fusion, const std::string& methodOption,
	std::optional<double> timeout)
{
	nav::NavigationSetup setup;
	const auto navConfig = lvf::common::openIniFile(config);
	setup.loop.loadFromConfigFile(*navConfig, "NavigationLoop");
	setup.navigatorConfig = readText(config);
	setup.navigatorConfigSource = config;
	{
		// MRPT's navigator loads [CHolonomicVFH] itself and turns a bad key
		// into an internal error: check the section here, naming the file.
		lvf::vfh::CHolonomicVFH::TOptions vfh;
		loadOwnSections(vfh, "CHolonomicVFH", *navConfig, config);
	}
	if (timeout)
	{
		if (!(*timeout > 0)) throw InputError("--timeout", "", "must be > 0");
		setup.loop.timeout = *timeout;
	}
	// The simulator's and the fusion's sections: from their own files if
	// given, else from --config if it has them (as --dump-config writes).
	if (!sensors.empty())
		setup.sensors.loadFromConfigFile(*lvf::common::openIniFile(sensors), kSensorsSection);
	else if (navConfig->sectionExists(kSensorsSection))
		loadOwnSections(setup.sensors, kSensorsSection, *navConfig, config);
	if (!fusion.empty())
		setup.fusion.loadFromConfigFile(*lvf::common::openIniFile(fusion), kFusionSection);
	else if (navConfig->sectionExists(kFusionSection))
		loadOwnSections(setup.fusion, kFusionSection, *navConfig, config);
	setup.method = methodOption.empty()
		? navConfig->read_string("CAbstractPTGBasedReactive", "holonomic_method", "CHolonomicND")
		: methodOption;
	nav::requireHolonomicMethod(setup.method, methodOption.empty() ? config : "--method");
	nav::requireNavigatorAccepts(setup.navigatorConfig, setup.method, config);
	return setup;
}

/** A single run's world, start and target: a seeded random room of `kind`,
 * else the world file (the box room by default), with --start and --target
 * over what it gives. */
nav::NavigationScenario chooseScenario(
	std::optional<uint32_t> seed, nav::RoomKind kind, const std::string& worldFile,
	const std::optional<std::string>& start, const std::optional<std::string>& target)
{
	nav::NavigationScenario scenario;
	if (seed)
		scenario = nav::randomScenario(*seed, kind);
	else
	{
		const std::string path = worldFile.empty() ? kDefaultWorld : worldFile;
		scenario.world = lvf::simulation::loadWorldFile(path);
		if (scenario.world.path.empty() && !start)
			throw InputError(path, "path", "no start pose (give a path or --start)");
		if (!scenario.world.target && !target)
			throw InputError(path, "target", "no navigation target (add target: [x, y] or give --target)");
		if (!scenario.world.path.empty()) scenario.start = scenario.world.path.front();
		if (scenario.world.target) scenario.target = *scenario.world.target;
	}
	if (start)
	{
		const auto v = parseNumbers(*start, 3, "--start");
		scenario.start = mrpt::math::TPose2D(v[0], v[1], mrpt::DEG2RAD(v[2]));
	}
	if (target)
	{
		const auto v = parseNumbers(*target, 2, "--target");
		scenario.target = mrpt::math::TPoint2D(v[0], v[1]);
	}
	return scenario;
}

int run(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"lvf-navigate: closed-loop navigation in a simulated world. Each control step the "
		"simulator renders the laser (and the stereo pair), the paper's fusion (or the laser "
		"alone) updates the robot's occupancy grid, MRPT's CReactiveNavigationSystem with the "
		"chosen holonomic method steers, and a differential-drive robot moves; collisions are "
		"judged against the full 3D world. Writes the trajectory over the true obstacles (PNG), "
		"the run's rawlog, MRPT's navigation log and a metrics line. --batch N runs N random "
		"rooms per room kind x methods x sensing and writes a table and CSV. Exit status of a "
		"single run: 0 reached, 3 collision / timeout / unreachable / navigator error, 4 scenario not runnable "
		"(start in collision, target inside an obstacle, NaN pose), 2 bad input.",
		' ', "0.1.0");
	TCLAP::ValueArg<std::string> argWorld("w", "world", "World file (YAML, see share/lvfusion/worlds/README.md; default: the box room, Fig. 7)", false, "", "W.yaml", cmd);
	TCLAP::ValueArg<int> argRandom("r", "random-world", "A random room of this seed instead of --world (first seed with --batch; default 1)", false, -1, "SEED", cmd);
	TCLAP::ValueArg<std::string> argRoomKinds("", "room-kind", "Random rooms: overhangs (tables, shelves, floating boxes) or visible (floor boxes only) (default: overhangs); with --batch a comma list (default: overhangs,visible)", false, "", "KIND[,KIND]", cmd);
	TCLAP::ValueArg<std::string> argMethod("m", "method", "Holonomic method (a registered class name: CHolonomicND, CHolonomicVFF, CHolonomicFullEval, ...; default: holonomic_method of the config)", false, "", "CLASS", cmd);
	TCLAP::ValueArg<std::string> argMethods("", "methods", "With --batch: comma list of holonomic methods (default: --method)", false, "", "A,B", cmd);
	TCLAP::ValueArg<std::string> argSensing("s", "sensing", "fused (laser + stereo, default) or laser; with --batch a comma list", false, "fused", "MODE", cmd);
	TCLAP::ValueArg<std::string> argConfig("c", "config", "Navigation INI: [NavigationLoop] plus MRPT's reactive navigator sections (default: " + kDefaultConfig + ")", false, kDefaultConfig, "FILE.ini", cmd);
	TCLAP::ValueArg<std::string> argSensors("", "sensors-config", "Simulator INI, section [CStereoLaserSimulator] (default: that section of --config if it has one, else built-in, see sensors.ini)", false, "", "FILE.ini", cmd);
	TCLAP::ValueArg<std::string> argFusion("", "fusion-config", "Fusion INI, section [CLaserStereoFusion] (default: that section of --config if it has one, else built-in, see fusion.ini)", false, "", "FILE.ini", cmd);
	TCLAP::ValueArg<std::string> argStart("", "start", "Start pose instead of the world's first path pose", false, "", "X,Y,DEG", cmd);
	TCLAP::ValueArg<std::string> argTarget("", "target", "Target instead of the world's", false, "", "X,Y", cmd);
	TCLAP::ValueArg<double> argTimeout("", "timeout", "Simulated seconds before giving up (default: [NavigationLoop] timeout)", false, 0, "S", cmd);
	TCLAP::ValueArg<int> argBatch("b", "batch", "Run N random rooms per room kind", false, 0, "N", cmd);
	TCLAP::ValueArg<std::string> argOutdir("o", "outdir", "Output folder (default: lvf-out)", false, "lvf-out", "DIR", cmd);
	lvf::common::ThreadsOption threads(cmd, "the simulator's two cameras and the fusion's model check and depth search");
	TCLAP::SwitchArg argQuiet("q", "quiet", "Print only the metrics line (or table) and errors", cmd);
	TCLAP::SwitchArg argDumpConfig("", "dump-config", "Print the complete configuration ([NavigationLoop], every MRPT navigator section and key, the simulator's and the fusion's sections; defaults overridden by --config, --sensors-config, --fusion-config, --method) and exit; it reads back as --config", cmd);
	if (!lvf::common::parseCommandLine(cmd, argc, argv)) return lvf::common::kExitOk;
	threads.apply();
	lvf::common::rejectRawlogNamedFolder(argOutdir.getValue(), "--outdir", "the run's rawlog is written inside it");

	lvf::registerAllClasses();
	nav::NavigationSetup setup = loadSetup(
		argConfig.getValue(), argSensors.getValue(), argFusion.getValue(), argMethod.getValue(), ifGiven(argTimeout));
	const std::string& method = setup.method;
	if (argDumpConfig.getValue())
	{
		std::cout << dumpConfig(setup);
		return lvf::common::kExitOk;
	}

	std::vector<nav::Sensing> sensings;
	for (const auto& s : splitList(argSensing.getValue())) sensings.push_back(nav::parseSensing(s, "--sensing"));
	if (sensings.empty()) throw InputError("--sensing", "", "give fused or laser");
	const bool batch = argBatch.isSet();
	if (argRandom.isSet() && argRandom.getValue() < 0) throw InputError("--random-world", "", "must be >= 0");
	if (!batch && argWorld.isSet() && argRandom.isSet()) throw InputError("--random-world", "", "give either --world or --random-world");
	std::vector<nav::RoomKind> kinds;
	for (const auto& k : splitList(argRoomKinds.getValue().empty() ? "overhangs,visible" : argRoomKinds.getValue()))
		kinds.push_back(nav::parseRoomKind(k, "--room-kind"));

	if (batch)
	{
		if (argBatch.getValue() < 1) throw InputError("--batch", "", "must be >= 1");
		if (argWorld.isSet() || argStart.isSet() || argTarget.isSet())
			throw InputError("--batch", "", "runs random rooms: --world, --start and --target do not apply");
		const std::vector<std::string> methods =
			splitList(argMethods.getValue().empty() ? method : argMethods.getValue());
		for (const auto& m : methods) nav::requireHolonomicMethod(m, "--methods");
		const uint32_t firstSeed = argRandom.isSet() ? uint32_t(argRandom.getValue()) : 1;
		return runBatch(argBatch.getValue(), firstSeed, kinds, methods, sensings, setup, argOutdir.getValue(), argQuiet.getValue());
	}
	if (argMethods.isSet()) throw InputError("--methods", "", "only with --batch (use --method)");
	if (sensings.size() != 1) throw InputError("--sensing", "", "a single run takes one sensing mode (lists only with --batch)");
	if (argRoomKinds.isSet() && !argRandom.isSet())
		throw InputError("--room-kind", "", "only for random rooms (with --random-world or --batch)");
	if (kinds.size() != 1 && argRoomKinds.isSet())
		throw InputError("--room-kind", "", "a single run takes one room kind (lists only with --batch)");
	setup.sensing = sensings.front();

	const auto seed = ifGiven(argRandom);  // checked >= 0 above
	const auto scenario = chooseScenario(
		seed ? std::optional(uint32_t(*seed)) : std::nullopt, kinds.front(), argWorld.getValue(), ifGiven(argStart),
		ifGiven(argTarget));
	return runSingle(scenario, setup, argOutdir.getValue(), argQuiet.getValue());
}

}  // namespace

int main(int argc, char** argv)
{
	return lvf::common::runApp(kApp, [&] { return run(argc, argv); });
}
