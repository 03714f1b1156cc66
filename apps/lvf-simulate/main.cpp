// lvf-simulate: renders a world file into an MRPT rawlog (2D laser + stereo
// pair + odometry) with ground truth beside it. See README.md, "lvf-simulate".

#include "GroundTruthWriter.h"
#include "PreviewImage.h"

#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/ProgressBar.h>
#include <lvfusion/common/ShippedFiles.h>
#include <lvfusion/common/RawlogWriter.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/plugin/registerAllClasses.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/RandomWorld.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/system/CTicTac.h>

#include <filesystem>
#include <iostream>
#include <optional>

using lvf::common::InputError;
using lvf::simulation::CStereoLaserSimulator;

namespace
{
const std::string kApp = "lvf-simulate";
const std::string kDefaultWorld =
	lvf::common::shippedFile("worlds/box_room.yaml", std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml");

CStereoLaserSimulator::TOptions loadOptions(const std::string& path)
{
	CStereoLaserSimulator::TOptions options;
	if (path.empty()) return options;  // built-in defaults = config/sensors.ini
	options.loadFromConfigFile(
		*lvf::common::openIniFile(path), "CStereoLaserSimulator");
	return options;
}

std::string fileSizeText(const std::string& path)
{
	const double mb = static_cast<double>(std::filesystem::file_size(path)) / 1e6;
	return mrpt::format("%.1f MB", mb);
}

/** What the run simulated, for the summary. */
struct Summary
{
	size_t frames = 0, inView = 0, hidden = 0;
	size_t seenHidden = 0;	//!< of the hidden, those whose obstacle both cameras see
};

/** --random-world SEED (none: not given) or --world FILE (`worldGiven`:
 * given by the user, not the default), not both; its path cut to the first
 * `frames` poses if that is fewer (0: all). */
lvf::simulation::World chooseWorld(std::optional<int> randomSeed, const std::string& worldFile, bool worldGiven, int frames)
{
	if (randomSeed && *randomSeed < 0) throw InputError("--random-world", "", "must be >= 0");
	if (randomSeed && worldGiven) throw InputError("--random-world", "", "give either --world or --random-world");
	auto world = randomSeed ? lvf::simulation::generateRandomWorld(static_cast<uint32_t>(*randomSeed))
							: lvf::simulation::loadWorldFile(worldFile);
	if (frames > 0 && static_cast<size_t>(frames) < world.path.size()) world.path.resize(static_cast<size_t>(frames));
	return world;
}

/** Counts a frame's bearings in view, hidden, and hidden but seen by both
 * cameras. */
void count(const CStereoLaserSimulator::Frame& frame, const std::vector<bool>& inView, const std::vector<bool>& hidden, Summary& s)
{
	s.frames++;
	for (size_t i = 0; i < inView.size(); i++)
	{
		s.inView += inView[i];
		s.hidden += hidden[i];
		s.seenHidden += hidden[i] && i < frame.seenTruthScan.size() &&
			lvf::metrics::seenByBothCameras(frame.seenTruthScan[i], frame.truthScan[i]);
	}
}

void printSummary(
	const lvf::simulation::World& world, const CStereoLaserSimulator::TOptions& options, const Summary& summary,
	double seconds, const std::string& rawlogPath, const std::string& format, const std::string& name,
	const std::string& outputDir)
{
	const auto& st = options.stereo;
	std::cout << mrpt::format(
		"%s: world '%s'%s: %zu boxes, %zu frame%s in %.2f s\n"
		"  laser %zu rays over %.0f deg; stereo %dx%d, baseline %.3f m\n"
		"  hidden bearings (in camera view, truth nearer than laser by > 0.15 m): %zu of %zu in view "
		"(%.1f per frame; %zu of them seen by both cameras)\n"
		"  wrote %s (%s, %s) and ground truth %s_* in %s\n",
		kApp.c_str(), world.name.c_str(), world.sourceFile.empty() ? " (seeded)" : (" (" + world.sourceFile + ")").c_str(),
		world.boxes.size(), summary.frames, summary.frames == 1 ? "" : "s", seconds, options.laser.rayCount(),
		options.laser.apertureDeg, st.ncols, st.nrows, st.baseline, summary.hidden, summary.inView,
		static_cast<double>(summary.hidden) / std::max<size_t>(1, summary.frames), summary.seenHidden,
		rawlogPath.c_str(), format.c_str(), fileSizeText(rawlogPath).c_str(), name.c_str(), outputDir.c_str());
}

int run(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"lvf-simulate: render a world (YAML) into an MRPT rawlog with a 2D "
		"laser (label LASER), a calibrated stereo pair (STEREO) and odometry, "
		"plus ground truth beside it: true poses, truth scans, the robot-band "
		"obstacle map (.gridmap.gz + PNG) and optionally left-image depth. "
		"With no arguments: the box-room world into ./lvf-out/.",
		' ', "0.1.0");
	TCLAP::ValueArg<std::string> argWorld(
		"w", "world", "World file (default: " + kDefaultWorld + ")", false,
		kDefaultWorld, "FILE.yaml", cmd);
	TCLAP::ValueArg<int> argRandomWorld(
		"r", "random-world",
		"Instead of --world, a seeded random room (floor boxes, floating boxes, "
		"a table, a wall shelf, some textureless walls: the worlds the tests "
		"score the fusion on) named random_SEED",
		false, -1, "SEED", cmd);
	TCLAP::ValueArg<std::string> argConfig(
		"c", "config",
		"Sensor configuration, MRPT INI; keys not given keep their defaults "
		"(listed with --dump-config, shipped as " +
			lvf::common::shippedFile("config/sensors.ini", std::string(LVF_SHARE_DIR) + "/config/sensors.ini") + ")",
		false, "", "FILE.ini", cmd);
	TCLAP::ValueArg<std::string> argOutdir(
		"o", "outdir", "Output folder (default: lvf-out)", false, "lvf-out",
		"DIR", cmd);
	TCLAP::ValueArg<std::string> argName(
		"n", "name", "Base name of the output files (default: the world's name)",
		false, "", "NAME", cmd);
	TCLAP::ValueArg<std::string> argFormat(
		"f", "format",
		"Rawlog layout: sf = actions/sensory frames (default), obs = "
		"observations only",
		false, "sf", "sf|obs", cmd);
	TCLAP::ValueArg<int> argFrames(
		"", "frames", "Simulate only the first N poses of the path (0: all of them)", false, 0,
		"N", cmd);
	TCLAP::ValueArg<int> argSeed(
		"s", "seed", "Override [CStereoLaserSimulator] seed", false, -1, "N", cmd);
	TCLAP::SwitchArg argDepth(
		"d", "depth", "Also write left-image ground-truth depth (PFM, metres)",
		cmd);
	TCLAP::SwitchArg argDumpConfig(
		"", "dump-config",
		"Print the complete configuration (defaults overridden by --config) "
		"and exit",
		cmd);
	TCLAP::SwitchArg argQuiet("q", "quiet", "Print nothing but errors", cmd);
	if (!lvf::common::parseCommandLine(cmd, argc, argv))
		return lvf::common::kExitOk;

	auto options = loadOptions(argConfig.getValue());
	if (argSeed.isSet())
	{
		if (argSeed.getValue() < 0) throw InputError("--seed", "", "must be >= 0");
		options.seed = static_cast<uint32_t>(argSeed.getValue());
	}
	if (argDumpConfig.getValue())
	{
		mrpt::config::CConfigFileMemory dump;
		options.saveToConfigFile(dump, "CStereoLaserSimulator");
		std::cout << dump.getContent();
		return lvf::common::kExitOk;
	}
	if (argFrames.getValue() < 0)
		throw InputError("--frames", "", "must be >= 0");
	const auto format = lvf::common::parseRawlogFormat(argFormat.getValue(), "--format");

	lvf::registerAllClasses();
	const auto world = chooseWorld(argRandomWorld.isSet() ? std::optional<int>(argRandomWorld.getValue()) : std::nullopt,
		argWorld.getValue(), argWorld.isSet(), argFrames.getValue());
	const std::string name = argName.getValue().empty() ? world.name : argName.getValue();
	if (!lvf::common::isPlainFileName(name)) throw InputError("--name", "", "'" + name + "' " + lvf::common::kPlainFileNameRule);
	const bool quiet = argQuiet.getValue();

	mrpt::system::CTicTac timer;
	CStereoLaserSimulator sim(world, options);
	lvf::common::rejectRawlogNamedFolder(argOutdir.getValue(), "--outdir", "the rawlog is written inside it as NAME.rawlog (-n NAME)");
	lvf::common::StagedOutputFiles files(argOutdir.getValue());
	lvf::common::RawlogWriter rawlog(files.stage(name + ".rawlog"), format);
	lvf::apps::GroundTruthWriter truth(files, name, argDepth.getValue());
	const lvf::metrics::HeightBand band{
		sim.world().robot.obstacleMinHeight, sim.world().robot.height};

	Summary summary;
	lvf::common::ProgressBar progress("simulating", sim.frameCount());
	for (size_t k = 0; k < sim.frameCount(); k++)
	{
		const auto frame = sim.simulateNextFrame(true);  // the depth for the seen truth, written if asked
		rawlog.append({frame.timestamp, frame.odometry, {frame.scan, frame.stereo}});
		truth.add(frame);
		const auto inView = lvf::metrics::bearingsInView(
			*frame.scan, frame.truthScan, *frame.stereo, band, options.laser.maxRange);
		const auto hidden =
			lvf::metrics::hiddenBearings(*frame.scan, frame.truthScan, inView);
		if (k == 0)
			lvf::apps::writePreviewImage(
				files.stage(name + "_preview.png"), frame, hidden, sim.world().robot);
		count(frame, inView, hidden, summary);
		if (!quiet) progress.update(k + 1);
	}
	rawlog.close();
	truth.writeObstacleMap(sim.world());
	truth.close();
	files.commit();

	if (!quiet)
		printSummary(world, options, summary, timer.Tac(), files.finalPath(name + ".rawlog"), argFormat.getValue(),
			name, files.outputDir());
	return lvf::common::kExitOk;
}

}  // namespace

int main(int argc, char** argv)
{
	return lvf::common::runApp(kApp, [&] { return run(argc, argv); });
}
