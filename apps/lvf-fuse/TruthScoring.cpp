#include "TruthScoring.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogReader.h>
#include <lvfusion/common/Suffixes.h>
#include <mrpt/core/format.h>
#include <mrpt/system/filesystem.h>

#include <filesystem>
#include <iostream>

namespace lvf::apps
{
namespace
{
const std::string kTruthSuffix = "_truth_scans.csv";

std::string ifExists(const std::string& path) { return mrpt::system::fileExists(path) ? path : ""; }

/** NAME_seen_truth_scans.csv beside NAME_truth_scans.csv. */
std::string seenTruthBeside(const std::string& truthPath)
{
	if (!lvf::common::endsWith(truthPath, kTruthSuffix)) return "";
	return ifExists(truthPath.substr(0, truthPath.size() - kTruthSuffix.size()) + "_seen" + kTruthSuffix);
}

std::vector<lvf::metrics::TruthScan> readIfNamed(const std::string& path)
{
	return path.empty() ? std::vector<lvf::metrics::TruthScan>{} : lvf::metrics::readTruthScans(path);
}

/** The truth scan of a frame's time stamp with its scan's number of
 * bearings, if any (from the frame as planned: before its scan is read). */
const lvf::metrics::TruthScan* truthScanOf(const std::vector<lvf::metrics::TruthScan>& truth, const FusionFrame& f)
{
	const auto* t = lvf::metrics::findTruthScan(truth, f.scanTime);
	return t && t->ranges.size() == f.scanBearings ? t : nullptr;
}
}  // namespace

TruthFiles loadTruthFiles(const std::string& input, const std::string& given)
{
	TruthFiles t;
	const std::filesystem::path in(input);
	t.path = !given.empty() ? given : ifExists((in.parent_path() / (lvf::common::rawlogName(input) + kTruthSuffix)).string());
	t.seenPath = seenTruthBeside(t.path);
	t.scans = readIfNamed(t.path);
	t.seenScans = readIfNamed(t.seenPath);
	return t;
}

void checkTruthFitsFrames(const TruthFiles& truth, const RawlogFrames& in, bool given, const std::string& app)
{
	if (truth.path.empty()) return;
	if (truth.scans.empty()) throw lvf::common::InputError(truth.path, "", "holds no truth scans");
	size_t fitting = 0;
	for (const auto& f : in.frames) fitting += truthScanOf(truth.scans, f) != nullptr;
	if (fitting == in.frames.size()) return;
	const std::string what = mrpt::format(
		"a truth scan (its time stamp and bearings) for %zu of the %zu frames to fuse (%zu truth scans of %zu "
		"bearings; the log's scans have %zu)",
		fitting, in.frames.size(), truth.scans.size(), truth.scans.front().ranges.size(), in.frames.front().scanBearings);
	if (given && fitting == 0) throw lvf::common::InputError(truth.path, "", what + ": the truth of another log?");
	std::cerr << app << ": warning: " << truth.path << ": " << what << "; only those are scored" << std::endl;
}

std::optional<FrameTruth> scoreAgainstTruth(
	const TruthFiles& truth, const FusionFrame& f, const lvf::fusion::CLaserStereoFusion::Result& r,
	const lvf::fusion::CLaserStereoFusion::TOptions& options)
{
	const auto* t = truthScanOf(truth.scans, f);
	if (!t) return std::nullopt;
	const auto* seen = truthScanOf(truth.seenScans, f);
	FrameTruth ft;
	ft.ranges = t->ranges;
	if (seen) ft.seenRanges = seen->ranges;
	ft.inView = lvf::metrics::bearingsInView(*f.scan, t->ranges, *f.stereo, options.band, options.depth.zMax);
	ft.hidden = lvf::metrics::hiddenBearings(*f.scan, t->ranges, ft.inView);
	ft.verdicts = lvf::metrics::judgeBearings(*f.scan, *r.fused, t->ranges, ft.inView, options.depth.zMax);
	ft.score = lvf::metrics::scoreVerdicts(
		ft.verdicts, *r.fused, t->ranges, options.depth.zMax, seen ? &seen->ranges : nullptr);
	return ft;
}

}  // namespace lvf::apps
