#pragma once
// What lvf-fuse needs from an input rawlog (either MRPT layout), found in a
// first pass that keeps nothing of the objects: every laser scan paired with
// the stereo observation nearest in time, where in the file the two are, and
// the robot's odometry pose at the scan. The second pass (FrameStream.h)
// reads them again, a few entries at a time: a real robot's log, with its
// images, does not fit in memory.

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <string>
#include <vector>

namespace lvf::apps
{
/** Where an observation is: its rawlog entry, and its place in that entry
 * (in a sensory frame; 0 for an observation that is an entry itself). */
struct ObservationPlace
{
	size_t entry = 0;
	size_t slot = 0;
};

struct FusionFrame
{
	ObservationPlace scanAt, stereoAt;
	double scanTime = 0;  //!< the scan's time stamp [s]
	size_t scanBearings = 0;  //!< and its number of rays
	mrpt::poses::CPose2D odometry;	//!< robot pose by odometry at the scan
	/** The objects, once the second pass has read them. */
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	mrpt::obs::CObservationStereoImages::Ptr stereo;

	/** The entry after which the frame's results are written: the later
	 * of its two. */
	size_t lastEntry() const { return std::max(scanAt.entry, stereoAt.entry); }
};

struct RawlogFrames
{
	size_t entries = 0;	 //!< objects in the file
	std::vector<FusionFrame> frames;  //!< in the scans' file order
	size_t scans = 0, stereoPairs = 0, unpairedScans = 0;
	bool hasOdometry = false;
	bool sensoryFrames = false;	 //!< actions/sensory-frames layout
};

/** Which sensors to fuse, by sensorLabel; empty: the log's only one. */
struct SensorLabels
{
	std::string laser, stereo;
};

/** Reads `path` once and pairs scans (CObservation2DRangeScan, not
 * labelled FUSED) with stereo pairs within `maxTimeDiff` seconds. Throws
 * InputError naming the record if the file is not a readable rawlog, and
 * naming the labels found if a chosen label is not among them or, with
 * none chosen, the log holds scans (or stereo pairs) of several sensors. */
RawlogFrames planRawlogFrames(const std::string& path, double maxTimeDiff, const SensorLabels& labels = {});

}  // namespace lvf::apps
