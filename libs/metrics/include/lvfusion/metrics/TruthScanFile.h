#pragma once
// Reads the truth scans lvf-simulate (and lvf-import-middlebury) write beside
// a rawlog: NAME_truth_scans.csv, a header, then per frame
// "frame,timestamp,r0,r1,..." with "inf" where nothing is in the band.

#include <string>
#include <vector>

namespace lvf::metrics
{
struct TruthScan
{
	double timestamp = 0;  //!< of the laser scan it belongs to [s]
	std::vector<float> ranges;
};

/** Throws lvf::common::InputError naming the file and line if malformed. */
std::vector<TruthScan> readTruthScans(const std::string& path);

/** The truth scan stamped within 1e-4 s of `timestamp`, or nullptr. */
const TruthScan* findTruthScan(const std::vector<TruthScan>& scans, double timestamp);

}  // namespace lvf::metrics
