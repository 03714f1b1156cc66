#pragma once
// The truth scan restricted to what both cameras see. truthScan()
// (GroundTruth.h) counts every obstacle in the band, also the ones outside
// the images: a table top above the picture at the edge of the view, a box
// at the left image's edge that the right camera, 12 cm to the right, does
// not see. No stereo method can find those; this scan says which obstacles
// one could, so that a recall can be read over them as well (lvf-fuse
// prints both when NAME_seen_truth_scans.csv lies beside its input).

#include <lvfusion/common/HeightBand.h>
#include <lvfusion/simulation/CameraRayTable.h>
#include <mrpt/img/TStereoCamera.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>
#include <opencv2/core.hpp>

#include <vector>

namespace lvf::simulation
{
class StereoSeenTruth
{
   public:
	/** @param leftCameraOnRobot, rightOfLeft the rig's poses (robot frame;
	 * right relative to left)
	 * @param margin pixels a point must lie inside both images: half a
	 * matching window (the fusion's 11x11 windows: 5) */
	StereoSeenTruth(
		const mrpt::img::TStereoCamera& calibration, const mrpt::poses::CPose3D& leftCameraOnRobot,
		const mrpt::poses::CPose3D& rightOfLeft, const HeightBand& band, int margin = 5);

	/** For each bearing of `scanGeometry` (its sensorPose, aperture, size):
	 * the horizontal range from the laser to the nearest point in the band
	 * that a left pixel sees (depth `leftDepth`, z in the left camera, inf:
	 * nothing) and that projects into the right image as well, each pixel
	 * given to the bearing nearest its point; +infinity where there is none.
	 * The right image's occlusions are not checked. */
	std::vector<float> scan(const cv::Mat1f& leftDepth, const mrpt::obs::CObservation2DRangeScan& scanGeometry) const;

   private:
	mrpt::img::TStereoCamera m_calibration;
	mrpt::poses::CPose3D m_leftCamera, m_rightOfLeft;
	HeightBand m_band;
	int m_margin;
	CameraRayTable m_leftRays;
};

}  // namespace lvf::simulation
