#pragma once
// What lvf-map needs from a rawlog (either MRPT layout, plain or lvf-fuse's
// output): per laser scan, the odometry increment since the previous scan as
// the particle filter's action, the scan itself, and the FUSED scan of the
// same time when lvf-fuse has added one.

#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <string>
#include <vector>

namespace lvf::apps
{
struct MapStep
{
	mrpt::obs::CActionCollection::Ptr action;  //!< odometry since the previous step
	mrpt::obs::CSensoryFrame::Ptr laserFrame;  //!< the laser scan(s) only: the PF's observation
	mrpt::obs::CObservation2DRangeScan::Ptr laser;
	mrpt::obs::CObservation2DRangeScan::Ptr fused;	//!< null without lvf-fuse
	mrpt::poses::CPose2D odometry;	//!< dead-reckoned pose at the scan
};

struct MapRun
{
	std::vector<MapStep> steps;
	size_t fusedScans = 0;
};

/** Reads `path`. In the observations-only layout the odometry increments
 * become actions with `obsOnlyModel` (pf-localization's
 * [DummyOdometryParams]); sensory-frame logs keep their own actions. Throws
 * InputError naming the file when it has no laser scan or no odometry. */
MapRun loadMapRun(
	const std::string& path, const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions& obsOnlyModel);

}  // namespace lvf::apps
