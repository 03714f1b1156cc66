#pragma once
// A Middlebury 2014 scene as one frame of a robot: the stereo pair on a
// virtual robot standing on the floor its ground truth shows, a horizontal
// laser slice synthesised from that ground truth, and the truth scan of the
// robot's height band. lvf-import-middlebury writes it as a rawlog;
// lvf-bench scores the fusion and the dense matchers on it in memory.

#include <lvfusion/common/HeightBand.h>
#include <lvfusion/middlebury/FloorFit.h>
#include <lvfusion/middlebury/MiddleburyScene.h>
#include <lvfusion/middlebury/ScanSynthesis.h>
#include <lvfusion/middlebury/VirtualRobotFrame.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include <optional>
#include <string>
#include <vector>

namespace lvf::middlebury
{
struct SceneImportOptions
{
	LaserSlice slice;  //!< the laser's height, thickness and range
	lvf::HeightBand band{0.05, 1.20};  //!< the robot's, for the truth scan [m]
	double resolutionRad = 0.5 * M_PI / 180;  //!< between laser rays
	/** The laser's aperture [rad]; none: the camera's horizontal field of
	 * view, symmetric about the robot's x axis. */
	std::optional<double> apertureRad;
	FloorFitOptions floor;
};

struct ImportedScene
{
	MiddleburyScene scene;
	FloorPlane floor;
	VirtualRobotFrame frame;
	ScanBearings bearings;
	mrpt::obs::CObservation2DRangeScan::Ptr scan;  //!< label LASER
	mrpt::obs::CObservationStereoImages::Ptr stereo;  //!< label STEREO
	std::vector<float> truth;  //!< per ray of `scan` [m]; inf: nothing in the band
};

/** Reads the scene folder `dir` and builds its frame, stamped `stamp`.
 * Throws lvf::common::InputError naming the file (a scene with no visible
 * floor names its disparity file). */
ImportedScene importScene(
	const std::string& dir, const SceneImportOptions& options, mrpt::Clock::time_point stamp);

}  // namespace lvf::middlebury
