#include "TruthScoring.h"

#include <mrpt/system/filesystem.h>

#include <filesystem>

namespace lvf::apps
{
namespace
{
const std::string kTruthSuffix = "_truth_scans.csv";

std::string ifExists(const std::string& path) { return mrpt::system::fileExists(path) ? path : ""; }

/** NAME_seen_truth_scans.csv beside NAME_truth_scans.csv. */
std::string seenTruthBeside(const std::string& truthPath)
{
	const size_t n = kTruthSuffix.size();
	if (truthPath.size() < n || truthPath.compare(truthPath.size() - n, n, kTruthSuffix)) return "";
	return ifExists(truthPath.substr(0, truthPath.size() - n) + "_seen" + kTruthSuffix);
}

std::vector<lvf::metrics::TruthScan> readIfNamed(const std::string& path)
{
	return path.empty() ? std::vector<lvf::metrics::TruthScan>{} : lvf::metrics::readTruthScans(path);
}

/** The truth scan of a frame's time stamp with the frame's bearings, if any. */
const lvf::metrics::TruthScan* truthScanOf(const std::vector<lvf::metrics::TruthScan>& truth, const FusionFrame& f)
{
	const auto* t = lvf::metrics::findTruthScan(truth, mrpt::Clock::toDouble(f.scan->timestamp));
	return t && t->ranges.size() == f.scan->getScanSize() ? t : nullptr;
}
}  // namespace

TruthFiles loadTruthFiles(const std::string& input, const std::string& given)
{
	TruthFiles t;
	const std::filesystem::path in(input);
	t.path = !given.empty() ? given : ifExists((in.parent_path() / (in.stem().string() + kTruthSuffix)).string());
	t.seenPath = seenTruthBeside(t.path);
	t.scans = readIfNamed(t.path);
	t.seenScans = readIfNamed(t.seenPath);
	return t;
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
	ft.score = lvf::metrics::scoreFusedScan(
		*f.scan, *r.fused, t->ranges, ft.inView, options.depth.zMax, seen ? &seen->ranges : nullptr);
	return ft;
}

}  // namespace lvf::apps
