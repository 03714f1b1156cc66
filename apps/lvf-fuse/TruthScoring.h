#pragma once
// lvf-fuse against ground truth: the truth scans of its input (--truth, or
// NAME_truth_scans.csv beside it, as lvf-simulate and lvf-import-middlebury
// write them; and NAME_seen_truth_scans.csv beside that, lvf-simulate's
// truth of what both cameras see), and DESIGN.md's figures for each frame.

#include "FusionOutputs.h"
#include "RawlogFrames.h"

#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/metrics/TruthScanFile.h>

#include <optional>
#include <string>
#include <vector>

namespace lvf::apps
{
struct TruthFiles
{
	std::string path, seenPath;	 //!< empty: none
	std::vector<lvf::metrics::TruthScan> scans, seenScans;
};

/** `given` (--truth) if not empty, else NAME_truth_scans.csv beside `input`
 * if it exists; the seen truth beside whichever it is, if it exists. */
TruthFiles loadTruthFiles(const std::string& input, const std::string& given);

/** Checks before the run that the truth scans fit the log's frames (a
 * truth scan with a frame's time stamp and its number of bearings):
 * InputError naming the file if `given` (--truth) and it scores none of
 * them; a warning line on stderr, beginning with `app`, if it scores only
 * some (or, found beside the input, none). */
void checkTruthFitsFrames(const TruthFiles& truth, const RawlogFrames& frames, bool given, const std::string& app);

/** The figures of one fused frame, if a truth scan has its time stamp and
 * its bearings; with a seen truth scan also the recall over what both
 * cameras see. */
std::optional<FrameTruth> scoreAgainstTruth(
	const TruthFiles& truth, const FusionFrame& frame, const lvf::fusion::CLaserStereoFusion::Result& result,
	const lvf::fusion::CLaserStereoFusion::TOptions& options);

}  // namespace lvf::apps
