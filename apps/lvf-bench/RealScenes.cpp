#include "RealScenes.h"

#include "MethodRuns.h"
#include "StageMedians.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/evaluation/RectifiedStereo.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/middlebury/SceneImport.h>

#include <algorithm>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <optional>

namespace lvf::bench
{
namespace
{
const std::string kFusionSceneRange = "fusion, the scene's range";

std::vector<std::string> sceneFolders(const std::string& root)
{
	std::vector<std::string> dirs;
	std::error_code ec;
	for (const auto& entry : std::filesystem::directory_iterator(root, ec))
		if (entry.is_directory()) dirs.push_back(entry.path().string());
	std::sort(dirs.begin(), dirs.end());
	return dirs;
}

void benchScene(const lvf::middlebury::ImportedScene& imported, int passes)
{
	const lvf::fusion::CLaserStereoFusion::TOptions options;  // lvf-fuse's defaults
	lvf::fusion::CLaserStereoFusion fusion(options);
	const auto& scan = *imported.scan;
	const auto& stereo = *imported.stereo;
	lvf::evaluation::RectifiedStereo rectified;
	rectified.prepare(stereo, imported.scene.name);
	cv::Mat1b left, right;
	rectified.rectify(stereo, left, right);
	// The dense matchers search the disparities the scene says it spans
	// (calib.txt's ndisp), not the robot's z_min: from 0.3 m, 400-610 of them,
	// most of the image's width. A narrower range only makes them faster.
	const auto& calib = imported.scene.calib;
	const double denseZMin = calib.ndisp > 0 ? calib.depth(calib.ndisp) : options.depth.zMin;
	// The fusion as shipped searches from the robot's z_min (0.3 m: up to
	// 443-643 px of disparity on these rigs); and over the scene's range, as the
	// dense matchers do.
	auto sceneRange = options;
	sceneRange.depth.zMin = denseZMin;
	lvf::fusion::CLaserStereoFusion fusionOverSceneRange(sceneRange);

	StageMedians times;
	std::map<std::string, mrpt::obs::CObservation2DRangeScan::Ptr> fused;
	// Each method its passes in turn (SeededRooms.cpp says why).
	auto fuseEachPass = [&](lvf::fusion::CLaserStereoFusion& method, const std::string& name) {
		for (int pass = 0; pass < passes; pass++)
		{
			const auto r = method.process(scan, stereo, imported.scene.name);
			recordFusionTimes(times, name, r.times);
			fused[name] = r.fused;
		}
	};
	fuseEachPass(fusion, kFusionName);
	fuseEachPass(fusionOverSceneRange, kFusionSceneRange);
	for (const auto& [matcher, name] : kDenseMethods)
		for (int pass = 0; pass < passes; pass++)
			fused[name] = denseFusedScan(left, right, rectified.geometry(), options, denseZMin, scan, matcher, &times, name);
	const auto inView = lvf::metrics::bearingsInView(scan, imported.truth, stereo, options.band, options.depth.zMax);
	std::cout << "  " << imported.scene.name << " (" << left.cols << "x" << left.rows << "; the dense matchers "
			  << (calib.ndisp > 0 ? "over its disparities 0-" + std::to_string(calib.ndisp) : std::string("from z_min"))
			  << ", from " << std::fixed << std::setprecision(2) << denseZMin
			  << " m), median time per frame and stage [ms]:\n";
	times.print(std::cout, kSgbmName, "    ");
	for (const auto& name : {kFusionName, kFusionSceneRange, kSgbmName, kBmName})
	{
		const auto s = lvf::metrics::scoreFusedScan(scan, *fused[name], imported.truth, inView, options.depth.zMax);
		std::cout << "    " << std::setw(27) << std::left << name << std::right << std::fixed << std::setprecision(3)
				  << " recall " << s.recall() << " of " << s.hidden << "  phantom rate " << s.phantomRate() << " of "
				  << s.inView << "  median range error " << s.rangeErrorMedian() << " m (hidden "
				  << s.hiddenRangeErrorMedian() << " m)\n";
	}
}
}  // namespace

void printRealScenes(const std::string& root, int passes)
{
	const auto dirs = sceneFolders(root);
	if (dirs.empty())
	{
		std::cout << "\nReal images: no Middlebury scenes under " << root
				  << " (lvf-bench --middlebury DIR; see ../shared/data/README.md)\n";
		return;
	}
	std::cout << "\nReal images, Middlebury 2014 scenes with a floor (" << root << "; one frame each, "
			  << passes << " passes, one thread; recall over the hidden bearings, phantom rate over those in "
			  << "view, against the ground truth; lvf-import-middlebury's laser, 0.30 m up):\n";
	std::vector<std::string> skipped;
	for (const auto& dir : dirs)
	{
		std::optional<lvf::middlebury::ImportedScene> imported;
		try
		{
			imported = lvf::middlebury::importScene(dir, {}, mrpt::Clock::fromDouble(1.7e9));
		}
		catch (const lvf::common::InputError&)
		{
			skipped.push_back(std::filesystem::path(dir).filename().string());
			continue;
		}
		benchScene(*imported, passes);
	}
	if (!skipped.empty())
	{
		std::cout << "  (no floor the importer accepts, or not a scene:";
		for (const auto& name : skipped) std::cout << " " << name;
		std::cout << ")\n";
	}
}

}  // namespace lvf::bench
