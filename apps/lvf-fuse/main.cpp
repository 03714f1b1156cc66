// lvf-fuse: the paper's laser-stereo fusion over a rawlog. See README.md.
//
// Two passes over the input (RawlogFrames.h pairs scans with stereo pairs,
// FrameStream.h fuses them as they are read again), the outputs staged
// until the run succeeds (FusionOutputs.h), the figures against ground truth
// where the input has it (TruthScoring.h).

#include "FrameStream.h"
#include "FusedLogWriter.h"
#include "FusionOutputs.h"
#include "RawlogFrames.h"
#include "TruthScoring.h"

#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/CountedNoun.h>
#include <lvfusion/common/GridInsertion.h>
#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/Medians.h>
#include <lvfusion/common/ProgressBar.h>
#include <lvfusion/common/RawlogReader.h>
#include <lvfusion/common/RawlogWriter.h>
#include <lvfusion/common/ShippedFiles.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/common/ThreadsOption.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/plugin/registerAllClasses.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/format.h>
#include <mrpt/system/CTicTac.h>

#include <filesystem>
#include <iostream>
#include <optional>
#include <sys/resource.h>

using lvf::common::InputError;
using lvf::fusion::CLaserStereoFusion;

namespace
{
const std::string kApp = "lvf-fuse";
const std::string kDefaultInput =
	lvf::common::shippedFile("rawlog_samples/box_room.rawlog", std::string(LVF_SAMPLES_DIR) + "/box_room.rawlog");

constexpr double kDefaultMaxTimeDiff = 0.05;	 // [s]
constexpr double kDefaultGridResolution = 0.05;	 // [m]

/** The command line, checked. */
struct Arguments
{
	std::string input, output, outdir, config, truth;
	lvf::apps::SensorLabels labels;
	double maxTimeDiff = kDefaultMaxTimeDiff, gridResolution = kDefaultGridResolution;
	size_t evalEvery = 1;
	bool dumpConfig = false, quiet = false, verbose = false, points = false;
	std::string threads;  //!< OpenCV's pool as set, for the summary ("2 threads")
};

/** InputError unless `output` can take the fused rawlog: it names a file,
 * not a folder, and not the input log itself (which would be overwritten
 * by the log it is being read into). */
void checkOutputRawlog(const std::string& output, const std::string& input)
{
	namespace fs = std::filesystem;
	if (fs::path(output).filename().empty() || fs::is_directory(output))
		throw InputError("--output", "", "names a folder, not a file (e.g. " + (fs::path(output) / "out.rawlog").string() + ")");
	std::error_code unknown;  // either missing: not the same file
	if (fs::equivalent(output, input, unknown))
		throw InputError("--output", "", "is the input rawlog " + input + ": write the fused log to another file");
}

/** Parses and checks the command line and sizes OpenCV's pool; none if
 * --help or --version was answered. */
std::optional<Arguments> parseArguments(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"lvf-fuse: fuse every 2D laser scan of a rawlog with the stereo pair "
		"nearest in time (Baltzakis et al. 2003): line segments, planar model, "
		"NCC model evaluation, focused epipolar depth search, fused virtual "
		"scan. Writes the input rawlog plus FUSED scans and EVAL pictures, "
		"laser-only and fused occupancy grids, and a per-frame CSV. With no "
		"arguments: the box-room sample into ./lvf-out/.",
		' ', "0.1.0");
	TCLAP::ValueArg<std::string> argInput("i", "input", "Input rawlog, either MRPT layout (default: " + kDefaultInput + ")", false, kDefaultInput, "IN.rawlog", cmd);
	TCLAP::ValueArg<std::string> argOutput("", "output", "Output rawlog (default: OUTDIR/NAME_fused.rawlog)", false, "", "OUT.rawlog", cmd);
	TCLAP::ValueArg<std::string> argConfig("c", "config", "Fusion configuration, MRPT INI; keys not given keep their defaults (--dump-config lists them all)", false, "", "FILE.ini", cmd);
	TCLAP::ValueArg<std::string> argOutdir("o", "outdir", "Folder for grids, CSV and (by default) the output rawlog (default: lvf-out)", false, "lvf-out", "DIR", cmd);
	TCLAP::ValueArg<std::string> argTruth("t", "truth", "Truth scans (CSV) to score against (default: IN_truth_scans.csv if it exists)", false, "", "FILE.csv", cmd);
	TCLAP::ValueArg<std::string> argLaserLabel("", "laser-label", "Fuse the 2D scans of this sensor (sensorLabel; default: the log's only laser)", false, "", "LABEL", cmd);
	TCLAP::ValueArg<std::string> argStereoLabel("", "stereo-label", "With the stereo pairs of this sensor (sensorLabel; default: the log's only stereo camera)", false, "", "LABEL", cmd);
	TCLAP::ValueArg<double> argMaxDt("", "max-time-diff", mrpt::format("Pair a scan with a stereo pair at most this far apart in time [s] (default %g)", kDefaultMaxTimeDiff), false, kDefaultMaxTimeDiff, "S", cmd);
	TCLAP::ValueArg<int> argEvalEvery("", "eval-every", "Add the evaluation picture (EVAL) of every N-th frame to the output rawlog; 0: none (default 1: every frame; a picture is about the size of a stereo pair)", false, 1, "N", cmd);
	TCLAP::SwitchArg argPoints("", "points", "Also write NAME_points.csv: every visual point of every frame (pixel, disparity, NCC, robot-frame position, bearing and range from the laser, found by the search, grown or remembered); thousands of rows a frame", cmd);
	TCLAP::ValueArg<double> argGridRes("", "grid-resolution", mrpt::format("Occupancy grid cell size [m], 0.005 to 5 (default %g)", kDefaultGridResolution), false, kDefaultGridResolution, "M", cmd);
	lvf::common::ThreadsOption threads(cmd);
	TCLAP::SwitchArg argDumpConfig("", "dump-config", "Print the complete configuration (defaults overridden by --config) and exit", cmd);
	TCLAP::SwitchArg argQuiet("q", "quiet", "Print nothing but errors and warnings", cmd);
	TCLAP::SwitchArg argVerbose("v", "verbose", "Also print each frame's figures (segments, pixels, points, bearings, time) as it is fused", cmd);
	if (!lvf::common::parseCommandLine(cmd, argc, argv)) return std::nullopt;

	if (!(argMaxDt.getValue() >= 0)) throw InputError("--max-time-diff", "", "must be >= 0");
	if (!(argGridRes.getValue() >= 0.005 && argGridRes.getValue() <= 5))	 // as lvf-map's grids
		throw InputError("--grid-resolution", "", "must be in [0.005, 5]");
	if (argEvalEvery.getValue() < 0) throw InputError("--eval-every", "", "must be >= 0");
	if (argOutput.isSet()) checkOutputRawlog(argOutput.getValue(), argInput.getValue());
	lvf::common::rejectRawlogNamedFolder(argOutdir.getValue(), "--outdir", "the fused rawlog's own name goes to --output");
	if (argQuiet.getValue() && argVerbose.getValue()) throw InputError("--verbose", "", "contradicts --quiet: give one of them");
	threads.apply();

	Arguments a;
	a.input = argInput.getValue();
	a.output = argOutput.getValue();
	a.outdir = argOutdir.getValue();
	a.config = argConfig.getValue();
	a.truth = argTruth.getValue();
	a.labels = {argLaserLabel.getValue(), argStereoLabel.getValue()};
	a.maxTimeDiff = argMaxDt.getValue();
	a.gridResolution = argGridRes.getValue();
	a.evalEvery = static_cast<size_t>(argEvalEvery.getValue());
	a.dumpConfig = argDumpConfig.getValue();
	a.points = argPoints.getValue();
	a.quiet = argQuiet.getValue();
	a.verbose = argVerbose.getValue();
	a.threads = threads.describe();
	return a;
}

CLaserStereoFusion::TOptions loadOptions(const std::string& path)
{
	CLaserStereoFusion::TOptions options;
	if (!path.empty())
		options.loadFromConfigFile(*lvf::common::openIniFile(path), "CLaserStereoFusion");
	return options;
}

/** The fusion's warnings are printed by the frame loop, one line each in
 * this app's words, with those of frames it could not fuse at all; its
 * DEBUG lines (each frame's figures) only with --verbose. */
void routeFusionLog(CLaserStereoFusion& fusion, bool verbose)
{
	fusion.logging_enable_console_output = false;
	if (!verbose) return;
	fusion.setMinLoggingLevel(mrpt::system::LVL_DEBUG);
	fusion.logRegisterCallback([](std::string_view msg, mrpt::system::VerbosityLevel level, auto, auto) {
		if (level == mrpt::system::LVL_DEBUG) std::cout << kApp << ": " << msg << std::endl;
	});
}

/** The most memory the process has held so far [MB]. */
double peakMemoryMB()
{
	rusage usage{};
	::getrusage(RUSAGE_SELF, &usage);
	return static_cast<double>(usage.ru_maxrss) / 1024;	 // kB on Linux
}

/** What the run counted, for the summary. */
struct Tally
{
	lvf::metrics::FusionScore score;  //!< over the frames a truth scan scored
	size_t badFrames = 0, laserAlone = 0, scored = 0;
	std::vector<double> fusionMs;  //!< the fusion's own time, per frame
	size_t replacedEarlier = 0;	 //!< FusedLogWriter::replaced()
	/** The rectified geometry, where a frame's pair had to be rectified. */
	std::optional<lvf::evaluation::RectifiedGeometry> rectified;
};

/** The fusion's time per frame: the median of the frames after the first,
 * which alone sets up its buffers and OpenCV's (on the shipped samples 4-6
 * times a later frame's time). */
std::string fusionTime(const std::vector<double>& ms, const std::string& threads)
{
	if (ms.empty()) return "fused no frame";
	if (ms.size() == 1)
		return mrpt::format("%.2f ms for its one frame (%s; a first frame sets up, later ones take much less)",
			ms.front(), threads.c_str());
	return mrpt::format("%.2f ms per frame (%s), the median; the first frame %.2f ms (setting up)",
		lvf::common::median({ms.begin() + 1, ms.end()}, 0), threads.c_str(), ms.front());
}

void printSummary(
	const Arguments& a, const lvf::apps::RawlogFrames& in, const lvf::apps::FrameStream& stream, const Tally& t,
	const lvf::apps::TruthFiles& truth, double seconds, const CLaserStereoFusion::TOptions& options,
	const std::string& wrote)
{
	const std::string noOdometry = in.hasOdometry
		? ""
		: std::string("; no odometry: grids assume the robot stood still") +
			(options.memory.maxTravel > 0 ? ", and no frame remembers the points of earlier ones" : "");
	using lvf::common::counted;
	std::cout << mrpt::format(
		"%s: %s: %s, %s, %s (%s, %s, %s on the laser alone) in %.2f s, %.0f MB of memory at most "
		"(%zu of %zu rawlog entries held at once)\n"
		"  fusion %s%s\n",
		kApp.c_str(), a.input.c_str(), counted(in.scans, "scan").c_str(), counted(in.stereoPairs, "stereo pair").c_str(),
		counted(in.frames.size(), "fused frame").c_str(), counted(in.unpairedScans, "unpaired scan").c_str(),
		counted(t.badFrames, "bad frame").c_str(), counted(t.laserAlone, "frame").c_str(), seconds, peakMemoryMB(),
		stream.entriesHeldAtMost(), in.entries,
		fusionTime(t.fusionMs, a.threads).c_str(), noOdometry.c_str());
	if (t.rectified)
		std::cout << mrpt::format(
			"  the stereo pairs rectified (a lens, or cameras not parallel; OpenCV's stereoRectify, "
			"rectify_alpha %.2f): f %.1f px, baseline %.3f m\n",
			options.rectifyAlpha, t.rectified->f, t.rectified->baseline);
	const auto& s = t.score;
	if (t.scored)
		std::cout << mrpt::format(
			"  against %s (%zu frame%s): recall %.3f of %zu hidden bearings, phantom rate %.4f "
			"of %zu in view, median range error %.3f m (hidden %.3f m)\n",
			truth.path.c_str(), t.scored, t.scored == 1 ? "" : "s", s.recall(), s.hidden, s.phantomRate(), s.inView,
			s.rangeErrorMedian(), s.hiddenRangeErrorMedian());
	if (t.scored && !truth.seenScans.empty())
		std::cout << mrpt::format(
			"  recall %.3f of the %zu of them whose obstacle both cameras see (%s)\n", s.seenRecall(), s.seenHidden,
			std::filesystem::path(truth.seenPath).filename().c_str());
	if (t.replacedEarlier)
		std::cout << "  " << counted(t.replacedEarlier, "observation")
				  << " of an earlier fusion in the input (FUSED scans, EVAL pictures) left out: the output holds "
					 "this run's\n";
	if (stream.externalImages())
		std::cout << "  " << stream.externalImages() << " images read from " << stream.externalImagesFolder()
				  << " (the output rawlog names them by absolute path)\n";
	std::cout << "  wrote " << wrote << "\n";
}

/** InputError naming what `in` lacks, if it has no 2D scans or no stereo
 * pairs at all (most of MRPT's sample logs have no stereo camera): not a
 * matter of --max-time-diff. */
void requireBothSensors(const std::string& input, const lvf::apps::RawlogFrames& in)
{
	using lvf::common::counted;
	const std::string scans = "2D laser scans (CObservation2DRangeScan)",
					  pairs = "stereo pairs (CObservationStereoImages)";
	if (in.scans == 0 && in.stereoPairs == 0)
		throw InputError(input, "", "holds neither " + scans + " nor " + pairs + ": nothing to fuse");
	if (in.scans == 0)
		throw InputError(input, "", "holds no " + scans + " to fuse its " + counted(in.stereoPairs, "stereo pair") + " with");
	if (in.stereoPairs == 0)
		throw InputError(input, "", "holds no " + pairs + " to fuse its " + counted(in.scans, "2D scan") + " with");
}

int run(int argc, char** argv)
{
	const auto args = parseArguments(argc, argv);
	if (!args) return lvf::common::kExitOk;
	const Arguments& a = *args;
	const auto options = loadOptions(a.config);
	if (a.dumpConfig)
	{
		mrpt::config::CConfigFileMemory dump;
		options.saveToConfigFile(dump, "CLaserStereoFusion");
		std::cout << dump.getContent();
		return lvf::common::kExitOk;
	}
	lvf::registerAllClasses();

	const std::string name = lvf::common::rawlogName(a.input);
	const auto truth = lvf::apps::loadTruthFiles(a.input, a.truth);
	mrpt::system::CTicTac timer;
	auto in = lvf::apps::planRawlogFrames(a.input, a.maxTimeDiff, a.labels);
	requireBothSensors(a.input, in);
	if (in.frames.empty())
		throw InputError(a.input, "", mrpt::format(
			"no laser scan has a stereo pair within %.3f s (%zu scans, %zu stereo pairs)", a.maxTimeDiff,
			in.scans, in.stereoPairs));
	lvf::apps::checkTruthFitsFrames(truth, in, !a.truth.empty(), kApp);

	// The outputs, staged; an explicit --output path beside its own folder.
	lvf::common::StagedOutputFiles files(a.outdir);
	std::unique_ptr<lvf::common::StagedOutputFiles> outputFile;
	std::string outputPath;
	if (!a.output.empty())
	{
		const std::filesystem::path output(a.output);
		outputFile = std::make_unique<lvf::common::StagedOutputFiles>(output.parent_path().string());
		outputPath = outputFile->stage(output.filename().string());
	}
	else
		outputPath = files.stage(name + "_fused.rawlog");
	lvf::apps::FusionOutputs outputs(files, name, a.gridResolution, a.points);
	lvf::common::RawlogWriter out(outputPath,
		in.sensoryFrames ? lvf::common::RawlogFormat::ActionsSensoryFrames : lvf::common::RawlogFormat::Observations);

	CLaserStereoFusion fusion(options);
	routeFusionLog(fusion, a.verbose);
	Tally tally;
	lvf::common::ProgressBar progress("fusing", in.frames.size());
	lvf::apps::FrameStream stream(a.input, in);
	auto fuseFrame = [&](size_t k, const lvf::apps::FusionFrame& f) {
		const std::string record = a.input + ": frame " + std::to_string(k);
		CLaserStereoFusion::Result r;
		try
		{
			r = fusion.process(*f.scan, *f.stereo, record,
				in.hasOdometry ? std::optional<mrpt::poses::CPose2D>(f.odometry) : std::nullopt);
		}
		catch (const InputError& e)
		{
			// One bad frame does not stop the run: warn, use the laser alone.
			r = CLaserStereoFusion::laserOnly(*f.scan, std::string(e.what()) + " (laser only)");
			tally.badFrames++;
		}
		for (const auto& w : r.warnings) std::cerr << kApp << ": warning: " << w << std::endl;
		tally.laserAlone += r.fellBackToLaser;	// bad frames, a suspect calibration, no valid range
		tally.fusionMs.push_back(r.times.total());
		if (r.rectified) tally.rectified = r.geometry;

		const auto frameTruth = lvf::apps::scoreAgainstTruth(truth, f, r, options);
		if (frameTruth) tally.score.add(frameTruth->score), tally.scored++;
		if (!outputs.add(k, *f.scan, r, f.odometry, frameTruth))
			std::cerr << kApp << ": warning: " << record << ": scan " << f.scan->sensorLabel
					  << ": its pose (odometry and sensor pose) is not finite or lies more than "
					  << lvf::common::kMaxGridGrowth << " m outside the grids: left out of them" << std::endl;
		lvf::apps::FrameStream::Results results{r.fused};
		if (!r.left.empty() && a.evalEvery > 0 && k % a.evalEvery == 0)
			results.push_back(lvf::apps::evaluationImage(r, f.scan->timestamp));
		// Images kept as files stay on disk until a frame reads them, and
		// go again after it.
		f.stereo->imageLeft.unload();
		f.stereo->imageRight.unload();
		if (!a.quiet && !a.verbose) progress.update(k + 1);	 // -v's lines instead
		return results;
	};
	lvf::apps::FusedLogWriter fusedLog(out);
	stream.run(fuseFrame, [&](const auto& entry, const auto& results) { fusedLog.write(entry, results); });
	tally.replacedEarlier = fusedLog.replaced();
	out.close();
	outputs.close();
	files.commit();
	if (outputFile) outputFile->commit();

	if (!a.quiet)
		printSummary(a, in, stream, tally, truth, timer.Tac(), options,
			(outputFile ? a.output : files.finalPath(name + "_fused.rawlog")) + ", " + name +
				"_{laser,fused}.gridmap.gz, " + name + "_grids.png, " + name +
				(a.points ? "_{frames,bearings,points}.csv in " : "_{frames,bearings}.csv in ") +
				files.outputDir());
	return lvf::common::kExitOk;
}

}  // namespace

int main(int argc, char** argv)
{
	return lvf::common::runApp(kApp, [&] { return run(argc, argv); });
}
