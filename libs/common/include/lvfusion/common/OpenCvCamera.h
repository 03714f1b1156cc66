#pragma once
// An MRPT camera (mrpt::img::TCamera) in OpenCV's terms, for
// cv::stereoRectify, cv::initUndistortRectifyMap, cv::projectPoints and
// cv::undistortPoints. One reading of a calibration for the renderer, the
// seen truth and the rectification alike.

#include <mrpt/img/TCamera.h>
#include <opencv2/core.hpp>

#include <vector>

namespace lvf::common
{
/** fx 0 cx / 0 fy cy / 0 0 1. */
cv::Matx33d openCvCameraMatrix(const mrpt::img::TCamera& camera);

/** Whether OpenCV's pin-hole functions can model the camera's lens:
 * MRPT's `none` and `plumb_bob` models, not `kannala_brandt` (fish-eye,
 * which OpenCV models with its own cv::fisheye functions). */
bool isPinholeModel(const mrpt::img::TCamera& camera);

/** The distortion coefficients as MRPT's model defines them
 * (TCamera::distortion): `none`: none (MRPT ignores the stored numbers);
 * `plumb_bob`: k1 k2 p1 p2 k3, and k4 k5 k6 (OpenCV's rational model) when
 * any of those is non-zero. Throws std::invalid_argument for a model that
 * is not a pin-hole one (isPinholeModel). */
std::vector<double> openCvDistortion(const mrpt::img::TCamera& camera);

/** Any non-zero coefficient in openCvDistortion(camera). */
bool hasLensDistortion(const mrpt::img::TCamera& camera);

}  // namespace lvf::common
