#pragma once
// What lvf-fuse needs from an input rawlog (either MRPT layout): every laser
// scan paired with the stereo observation nearest in time, and the robot's
// odometry pose at each scan.

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/serialization/CSerializable.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>
#include <vector>

namespace lvf::apps
{
struct FusionFrame
{
	size_t scanEntry = 0;  //!< rawlog entry holding the scan
	size_t stereoEntry = 0;	 //!< rawlog entry holding the stereo pair
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	mrpt::obs::CObservationStereoImages::Ptr stereo;
	double stereoDelay = 0;	 //!< stereo minus scan timestamp [s]
	mrpt::poses::CPose2D odometry;	//!< robot pose by odometry at the scan
};

struct RawlogFrames
{
	/** Every object of the file, in order (observations, or actions and
	 * sensory frames). */
	std::vector<mrpt::serialization::CSerializable::Ptr> entries;
	std::vector<FusionFrame> frames;
	size_t scans = 0, stereoPairs = 0, unpairedScans = 0;
	bool hasOdometry = false;
	bool sensoryFrames = false;	 //!< actions/sensory-frames layout
	/** Images kept as files beside the log (ExternalImages.h), each now
	 * named by its absolute path; loaded only when a frame reads them. */
	size_t externalImages = 0;
	std::string externalImagesDirectory;  //!< where they are
};

/** Which sensors to fuse, by sensorLabel; empty: the log's only one. */
struct SensorLabels
{
	std::string laser, stereo;
};

/** Loads `path` (pointing its external images at their files) and pairs scans (CObservation2DRangeScan, not labelled
 * FUSED) with stereo pairs within `maxTimeDiff` seconds. Throws InputError
 * naming the record if the file is not a readable rawlog, and naming the
 * labels found if a chosen label is not among them or, with none chosen,
 * the log holds scans (or stereo pairs) of several sensors. */
RawlogFrames loadRawlogFrames(const std::string& path, double maxTimeDiff, const SensorLabels& labels = {});

}  // namespace lvf::apps
