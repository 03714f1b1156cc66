// lvf-import-middlebury: one Middlebury 2014 stereo scene with ground-truth
// disparity -> an lvfusion rawlog (the stereo pair + a 2D laser synthesised
// from the ground truth, on a virtual robot standing on the floor the ground
// truth shows) with truth scans beside it, so that lvf-fuse can be scored on
// real images (issue 3). Options: --help.

#include "TruthFiles.h"

#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogWriter.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/middlebury/SceneImport.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <iostream>

using lvf::common::InputError;

namespace
{
const std::string kApp = "lvf-import-middlebury";
/** Middlebury images carry no time: every import is stamped with
 * lvf-simulate's default start time, so that imports are reproducible. */
const double kTimestamp = 1.7e9;

size_t countTrue(const std::vector<bool>& v) { return static_cast<size_t>(std::count(v.begin(), v.end(), true)); }

int run(int argc, char** argv)
{
	TCLAP::CmdLine cmd(
		"lvf-import-middlebury: turn a Middlebury 2014 scene (im0.png, im1.png, "
		"calib.txt, disp0GT.pfm, mask0nocc.png) into an MRPT rawlog with the "
		"stereo pair (label STEREO) and a horizontal 2D laser (LASER) "
		"synthesised from the ground truth, on a virtual robot standing on the "
		"floor fitted to the ground truth; plus the truth scans (robot height "
		"band) and the robot's pose beside it, as lvf-simulate writes them.",
		' ', "0.1.0");
	TCLAP::ValueArg<std::string> argScene("s", "scene", "Middlebury scene folder, e.g. .../middlebury/Motorcycle", true, "", "DIR", cmd);
	// --out, and --outdir as the other programs call it.
	TCLAP::ValueArg<std::string> argOut("o", "out", "Output folder: NAME.rawlog, NAME_truth_scans.csv, NAME_gt_poses.txt (NAME: the scene folder's name)", true, "", "DIR");
	TCLAP::ValueArg<std::string> argOutdir("", "outdir", "The same as --out", true, "", "DIR");
	cmd.xorAdd(argOut, argOutdir);
	TCLAP::ValueArg<double> argLaserHeight("", "laser-height", "Height of the synthesised laser above the floor [m] (default 0.30)", false, 0.30, "H", cmd);
	TCLAP::ValueArg<double> argRobotHeight("", "robot-height", "Top of the robot height band, for the truth scans [m] (default 1.20)", false, 1.20, "H", cmd);
	TCLAP::ValueArg<double> argObstacleMin("", "obstacle-min-height", "Bottom of the robot height band [m] (default 0.05)", false, 0.05, "H", cmd);
	TCLAP::ValueArg<double> argMaxRange("", "max-range", "Laser maximum range: no ground truth nearer is no return [m] (default 8)", false, 8.0, "R", cmd);
	TCLAP::ValueArg<double> argFov("", "fov-deg", "Laser aperture [deg] (default: the camera's horizontal field of view, symmetric about the robot's x axis)", false, 0, "A", cmd);
	TCLAP::ValueArg<double> argResolution("", "resolution-deg", "Angle between laser rays [deg] (default 0.5)", false, 0.5, "R", cmd);
	TCLAP::SwitchArg argQuiet("q", "quiet", "Print nothing but errors", cmd);
	if (!lvf::common::parseCommandLine(cmd, argc, argv)) return lvf::common::kExitOk;

	lvf::middlebury::SceneImportOptions options;
	options.slice.height = argLaserHeight.getValue();
	options.slice.maxRange = argMaxRange.getValue();
	options.band = {argObstacleMin.getValue(), argRobotHeight.getValue()};
	options.resolutionRad = mrpt::DEG2RAD(argResolution.getValue());
	if (argFov.isSet()) options.apertureRad = mrpt::DEG2RAD(argFov.getValue());
	const auto& slice = options.slice;
	const auto& band = options.band;
	if (!(slice.height > 0)) throw InputError("--laser-height", "", "must be > 0");
	if (!(band.low >= 0)) throw InputError("--obstacle-min-height", "", "must be >= 0");
	if (!(band.high > band.low)) throw InputError("--robot-height", "", "must be above --obstacle-min-height");
	if (!(slice.height < band.high))
		throw InputError("--laser-height", "", "must be below --robot-height: the laser is on the robot");
	if (!(slice.maxRange > 0)) throw InputError("--max-range", "", "must be > 0");
	if (!(argResolution.getValue() > 0 && argResolution.getValue() <= 10))
		throw InputError("--resolution-deg", "", "must be in (0, 10]");
	if (argFov.isSet() && !(argFov.getValue() >= argResolution.getValue() && argFov.getValue() <= 360))
		throw InputError("--fov-deg", "", "must be in [--resolution-deg, 360]");

	mrpt::system::CTicTac timer;
	const auto stamp = mrpt::Clock::fromDouble(kTimestamp);
	const auto imported = lvf::middlebury::importScene(argScene.getValue(), options, stamp);
	const auto& [scene, floor, frame, bearings, scan, stereo, truth] = imported;
	const auto inView = lvf::metrics::bearingsInView(*scan, truth, *stereo, band, slice.maxRange);
	const auto hidden = lvf::metrics::hiddenBearings(*scan, truth, inView);

	const std::string outdir = argOut.isSet() ? argOut.getValue() : argOutdir.getValue();
	lvf::common::rejectRawlogNamedFolder(outdir, argOut.isSet() ? "--out" : "--outdir", "the rawlog is written inside it as NAME.rawlog");
	lvf::common::StagedOutputFiles files(outdir);
	{
		lvf::common::RawlogWriter rawlog(
			files.stage(scene.name + ".rawlog"), lvf::common::RawlogFormat::Observations);
		rawlog.append({stamp, mrpt::poses::CPose2D(), {scan, stereo}});
		rawlog.close();
	}
	lvf::apps::writeTruthScan(files.stage(scene.name + "_truth_scans.csv"), *scan, truth);
	lvf::apps::writeGroundTruthPose(files.stage(scene.name + "_gt_poses.txt"), stamp);
	files.commit();

	if (!argQuiet.getValue())
	{
		size_t valid = 0, withTruth = 0;
		for (size_t i = 0; i < scan->getScanSize(); i++)
		{
			valid += scan->getScanRangeValidity(i);
			withTruth += std::isfinite(truth[i]);
		}
		const auto& c = scene.calib;
		std::cout << mrpt::format(
			"%s: %s (%dx%d, f %.1f px, baseline %.3f m): %zu ground-truth points "
			"(%zu pixels unknown) in %.2f s\n"
			"  floor: %zu of %zu points below the image centre within +-%.0f mm, RMS %.1f mm "
			"(median %.1f mm); camera %.3f m above it, tilted %.1f deg down, roll %.1f deg\n"
			"  laser at %.2f m: %zu of %zu rays valid (%.1f deg aperture, %.2f deg steps, max "
			"range %.1f m)\n"
			"  truth (band %.2f-%.2f m): %zu bearings with an obstacle; hidden bearings (in "
			"camera view, truth nearer than laser by > 0.15 m): %zu of %zu in view\n"
			"  wrote %s, %s_truth_scans.csv, %s_gt_poses.txt in %s\n",
			kApp.c_str(), scene.name.c_str(), c.width, c.height, c.f, c.baseline,
			scene.points.size(), scene.unknownPixels, timer.Tac(), floor.inliers,
			floor.candidates, 1000 * options.floor.inlierBand, 1000 * floor.rms, 1000 * floor.medianResidual, frame.cameraHeight(),
			frame.tiltDeg(), frame.rollDeg(), slice.height, valid, scan->getScanSize(),
			mrpt::RAD2DEG(bearings.aperture), mrpt::RAD2DEG(bearings.step()), slice.maxRange,
			band.low, band.high, withTruth, countTrue(hidden), countTrue(inView),
			files.finalPath(scene.name + ".rawlog").c_str(), scene.name.c_str(), scene.name.c_str(),
			files.outputDir().c_str());
	}
	return lvf::common::kExitOk;
}

}  // namespace

int main(int argc, char** argv)
{
	return lvf::common::runApp(kApp, [&] { return run(argc, argv); });
}
