// lvf-fuse: the paper's laser-stereo fusion over a rawlog. See README.md.

#include "FrameStream.h"
#include "FusionOutputs.h"
#include "RawlogFrames.h"

#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/ProgressBar.h>
#include <lvfusion/common/RawlogWriter.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/common/ThreadsOption.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/metrics/TruthScanFile.h>
#include <lvfusion/plugin/registerAllClasses.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/system/CTicTac.h>
#include <mrpt/system/filesystem.h>

#include <filesystem>
#include <iostream>
#include <sys/resource.h>

using lvf::common::InputError;
using lvf::fusion::CLaserStereoFusion;

namespace
{
const std::string kApp = "lvf-fuse";
const std::string kDefaultInput = std::string(LVF_SAMPLES_DIR) + "/box_room.rawlog";

CLaserStereoFusion::TOptions loadOptions(const std::string& path)
{
	CLaserStereoFusion::TOptions options;
	if (!path.empty())
		options.loadFromConfigFile(*lvf::common::openIniFile(path), "CLaserStereoFusion");
	return options;
}

/** "dir/name.rawlog" -> "name". */
std::string baseName(const std::string& path) { return std::filesystem::path(path).stem().string(); }

/** --truth if given, else NAME_truth_scans.csv beside the input if it
 * exists (what lvf-simulate and lvf-import-middlebury write), else none. */
std::string truthScansFor(const std::string& input, const std::string& given)
{
	if (!given.empty()) return given;
	const std::string beside =
		(std::filesystem::path(input).parent_path() / (baseName(input) + "_truth_scans.csv")).string();
	return mrpt::system::fileExists(beside) ? beside : "";
}

/** NAME_seen_truth_scans.csv beside NAME_truth_scans.csv if it exists
 * (lvf-simulate writes it: what both cameras see), else none. */
std::string seenTruthScansFor(const std::string& truthPath)
{
	const std::string suffix = "_truth_scans.csv";
	if (truthPath.size() < suffix.size() || truthPath.compare(truthPath.size() - suffix.size(), suffix.size(), suffix))
		return "";
	const std::string seen = truthPath.substr(0, truthPath.size() - suffix.size()) + "_seen" + suffix;
	return mrpt::system::fileExists(seen) ? seen : "";
}

/** The truth scan of a frame's time stamp with the frame's bearings, if any. */
const lvf::metrics::TruthScan* truthScanOf(
	const std::vector<lvf::metrics::TruthScan>& truth, const lvf::apps::FusionFrame& f)
{
	const auto* t = lvf::metrics::findTruthScan(truth, mrpt::Clock::toDouble(f.scan->timestamp));
	return t && t->ranges.size() == f.scan->getScanSize() ? t : nullptr;
}

/** DESIGN.md's figures for one frame, if a truth scan has its time stamp
 * and its bearings; with the seen truth (may be empty) also the recall over
 * what both cameras see. */
std::optional<lvf::apps::FrameTruth> scoreAgainstTruth(
	const std::vector<lvf::metrics::TruthScan>& truth, const std::vector<lvf::metrics::TruthScan>& seenTruth,
	const lvf::apps::FusionFrame& f, const CLaserStereoFusion::Result& r, const CLaserStereoFusion::TOptions& options)
{
	const auto* t = truthScanOf(truth, f);
	if (!t) return std::nullopt;
	const auto* seen = truthScanOf(seenTruth, f);
	lvf::apps::FrameTruth ft;
	ft.ranges = t->ranges;
	if (seen) ft.seenRanges = seen->ranges;
	ft.inView = lvf::metrics::bearingsInView(*f.scan, t->ranges, *f.stereo, options.band, options.depth.zMax);
	ft.hidden = lvf::metrics::hiddenBearings(*f.scan, t->ranges, ft.inView);
	ft.score = lvf::metrics::scoreFusedScan(
		*f.scan, *r.fused, t->ranges, ft.inView, options.depth.zMax, seen ? &seen->ranges : nullptr);
	return ft;
}

/** One input entry, as it was, then the results of the frames that end at
 * it: inside the sensory frame in that layout, after the entry otherwise. */
void writeWithResults(
	lvf::common::RawlogWriter& out, const mrpt::serialization::CSerializable& entry,
	const lvf::apps::FrameStream::Results& results)
{
	const auto* sf = dynamic_cast<const mrpt::obs::CSensoryFrame*>(&entry);
	if (sf && !results.empty())
	{
		mrpt::obs::CSensoryFrame withResults(*sf);
		for (const auto& o : results) withResults.insert(o);
		out.appendEntry(withResults);
		return;
	}
	out.appendEntry(entry);
	for (const auto& o : results) out.appendEntry(*o);
}

/** The most memory the process has held so far [MB]. */
double peakMemoryMB()
{
	rusage usage{};
	::getrusage(RUSAGE_SELF, &usage);
	return static_cast<double>(usage.ru_maxrss) / 1024;	 // kB on Linux
}

int run(int argc, char** argv)
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
	TCLAP::ValueArg<double> argMaxDt("", "max-time-diff", "Pair a scan with a stereo pair at most this far apart in time [s] (default 0.05)", false, 0.05, "S", cmd);
	TCLAP::ValueArg<int> argEvalEvery("", "eval-every", "Add the evaluation picture (EVAL) of every N-th frame to the output rawlog; 0: none (default 1: every frame; a picture is about the size of a stereo pair)", false, 1, "N", cmd);
	TCLAP::ValueArg<double> argGridRes("", "grid-resolution", "Occupancy grid cell size [m], 0.005 to 5 (default 0.05)", false, 0.05, "M", cmd);
	lvf::common::ThreadsOption threads(cmd);
	TCLAP::SwitchArg argDumpConfig("", "dump-config", "Print the complete configuration (defaults overridden by --config) and exit", cmd);
	TCLAP::SwitchArg argQuiet("q", "quiet", "Print nothing but errors and warnings", cmd);
	TCLAP::SwitchArg argVerbose("v", "verbose", "Also print each frame's figures (segments, pixels, points, bearings, time) as it is fused", cmd);
	if (!lvf::common::parseCommandLine(cmd, argc, argv)) return lvf::common::kExitOk;

	const auto options = loadOptions(argConfig.getValue());
	if (argDumpConfig.getValue())
	{
		mrpt::config::CConfigFileMemory dump;
		options.saveToConfigFile(dump, "CLaserStereoFusion");
		std::cout << dump.getContent();
		return lvf::common::kExitOk;
	}
	if (!(argMaxDt.getValue() >= 0)) throw InputError("--max-time-diff", "", "must be >= 0");
	if (!(argGridRes.getValue() >= 0.005 && argGridRes.getValue() <= 5))	 // as lvf-map's grids
		throw InputError("--grid-resolution", "", "must be in [0.005, 5]");
	if (argEvalEvery.getValue() < 0) throw InputError("--eval-every", "", "must be >= 0");
	if (argOutput.isSet() && std::filesystem::path(argOutput.getValue()).filename().empty())
		throw InputError("--output", "", "names a folder, not a file (e.g. " + argOutput.getValue() + "out.rawlog)");
	const auto evalEvery = static_cast<size_t>(argEvalEvery.getValue());
	threads.apply();
	lvf::registerAllClasses();

	const std::string input = argInput.getValue();
	const std::string name = baseName(input);
	const std::string truthPath = truthScansFor(input, argTruth.getValue());
	const auto truth = truthPath.empty() ? std::vector<lvf::metrics::TruthScan>{}
										 : lvf::metrics::readTruthScans(truthPath);
	const std::string seenTruthPath = seenTruthScansFor(truthPath);
	const auto seenTruth = seenTruthPath.empty() ? std::vector<lvf::metrics::TruthScan>{}
												 : lvf::metrics::readTruthScans(seenTruthPath);
	mrpt::system::CTicTac timer;
	auto in = lvf::apps::planRawlogFrames(
		input, argMaxDt.getValue(), {argLaserLabel.getValue(), argStereoLabel.getValue()});
	if (in.frames.empty())
		throw InputError(input, "", mrpt::format(
			"no laser scan has a stereo pair within %.3f s (%zu scans, %zu stereo pairs)",
			argMaxDt.getValue(), in.scans, in.stereoPairs));

	lvf::common::StagedOutputFiles files(argOutdir.getValue());
	const std::string outName = argOutput.getValue().empty() ? name + "_fused.rawlog" : "";
	// An explicit --output path is staged beside its own folder.
	std::unique_ptr<lvf::common::StagedOutputFiles> outputFile;
	std::string outputPath;
	if (outName.empty())
	{
		const std::filesystem::path output(argOutput.getValue());
		outputFile = std::make_unique<lvf::common::StagedOutputFiles>(output.parent_path().string());
		outputPath = outputFile->stage(output.filename().string());
	}
	else
		outputPath = files.stage(outName);

	lvf::apps::FusionOutputs outputs(files, name, argGridRes.getValue());
	CLaserStereoFusion fusion(options);
	const bool quiet = argQuiet.getValue();
	// The fusion's warnings are printed below, one line each in this app's
	// words, with those of frames it could not fuse at all; its DEBUG
	// lines (each frame's figures) only when asked.
	fusion.logging_enable_console_output = false;
	const bool verbose = argVerbose.getValue() && !quiet;
	if (verbose)
	{
		fusion.setMinLoggingLevel(mrpt::system::LVL_DEBUG);
		fusion.logRegisterCallback([](std::string_view msg, mrpt::system::VerbosityLevel level, auto, auto) {
			if (level == mrpt::system::LVL_DEBUG) std::cout << kApp << ": " << msg << std::endl;
		});
	}
	lvf::metrics::FusionScore total;
	size_t badFrames = 0, laserAlone = 0, scored = 0;
	double timeSum = 0;
	lvf::common::ProgressBar progress("fusing", in.frames.size());
	lvf::common::RawlogWriter out(outputPath,
		in.sensoryFrames ? lvf::common::RawlogFormat::ActionsSensoryFrames : lvf::common::RawlogFormat::Observations);
	lvf::apps::FrameStream stream(input, in);
	auto fuseFrame = [&](size_t k, const lvf::apps::FusionFrame& f) {
		const std::string record = input + ": frame " + std::to_string(k);
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
			badFrames++;
		}
		for (const auto& w : r.warnings) std::cerr << kApp << ": warning: " << w << std::endl;
		laserAlone += r.fellBackToLaser;  // bad frames, a suspect calibration, no valid range
		timeSum += r.times.total();

		const auto frameTruth = scoreAgainstTruth(truth, seenTruth, f, r, options);
		if (frameTruth) total.add(frameTruth->score), scored++;
		outputs.add(k, *f.scan, r, f.odometry, frameTruth);
		lvf::apps::FrameStream::Results results{r.fused};
		if (!r.left.empty() && evalEvery > 0 && k % evalEvery == 0)
			results.push_back(lvf::apps::evaluationImage(r, f.scan->timestamp));
		// Images kept as files stay on disk until a frame reads them, and
		// go again after it.
		f.stereo->imageLeft.unload();
		f.stereo->imageRight.unload();
		if (!quiet && !verbose) progress.update(k + 1);	// -v's lines instead
		return results;
	};
	stream.run(fuseFrame, [&](const auto& entry, const auto& results) { writeWithResults(out, entry, results); });
	out.close();
	outputs.close();
	files.commit();
	if (outputFile) outputFile->commit();

	if (!quiet)
	{
		std::string noOdometry;
		if (!in.hasOdometry)
			noOdometry = std::string("; no odometry: grids assume the robot stood still") +
				(options.memory.maxTravel > 0 ? ", and no frame remembers the points of earlier ones" : "");
		std::cout << mrpt::format(
			"%s: %s: %zu scans, %zu stereo pairs, %zu fused frames (%zu unpaired scans, "
			"%zu bad frames, %zu frames on the laser alone) in %.2f s, %.0f MB of memory at most "
			"(%zu of %zu rawlog entries held at once)\n"
			"  fusion %.2f ms per frame (%s)%s\n",
			kApp.c_str(), input.c_str(), in.scans, in.stereoPairs, in.frames.size(),
			in.unpairedScans, badFrames, laserAlone, timer.Tac(), peakMemoryMB(), stream.entriesHeldAtMost(),
			in.entries, timeSum / double(in.frames.size()), threads.describe().c_str(), noOdometry.c_str());
		if (scored)
			std::cout << mrpt::format(
				"  against %s (%zu frame%s): recall %.3f of %zu hidden bearings, phantom rate %.4f "
				"of %zu in view, median range error %.3f m (hidden %.3f m)\n",
				truthPath.c_str(), scored, scored == 1 ? "" : "s", total.recall(), total.hidden, total.phantomRate(),
				total.inView, total.rangeErrorMedian, total.hiddenRangeErrorMedian);
		if (scored && !seenTruth.empty())
			std::cout << mrpt::format(
				"  recall %.3f of the %zu of them whose obstacle both cameras see (%s)\n", total.seenRecall(),
				total.seenHidden, std::filesystem::path(seenTruthPath).filename().c_str());
		if (stream.externalImages())
			std::cout << "  " << stream.externalImages() << " images read from " << stream.externalImagesFolder()
					  << " (the output rawlog names them by absolute path)\n";
		std::cout << "  wrote " << (outputFile ? argOutput.getValue() : files.finalPath(outName))
				  << ", " << name << "_{laser,fused}.gridmap.gz, " << name << "_grids.png, "
				  << name << "_{frames,bearings}.csv in " << files.outputDir() << "\n";
	}
	return lvf::common::kExitOk;
}

}  // namespace

int main(int argc, char** argv)
{
	return lvf::common::runApp(kApp, [&] { return run(argc, argv); });
}
