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

/** The figures of one fused frame, if a truth scan has its time stamp and
 * its bearings; with a seen truth scan also the recall over what both
 * cameras see. */
std::optional<FrameTruth> scoreAgainstTruth(
	const TruthFiles& truth, const FusionFrame& frame, const lvf::fusion::CLaserStereoFusion::Result& result,
	const lvf::fusion::CLaserStereoFusion::TOptions& options);

}  // namespace lvf::apps
