#pragma once
// An MRPT camera (mrpt::img::TCamera) in OpenCV's terms, for
// cv::stereoRectify, cv::initUndistortRectifyMap, cv::projectPoints and
// cv::undistortPoints. One reading of a calibration for the renderer, the
// seen truth and the rectification alike.

#include <mrpt/img/TCamera.h>
#include <opencv2/core.hpp>

#include <optional>
#include <vector>

namespace lvf::common
{
/** fx 0 cx / 0 fy cy / 0 0 1. */
cv::Matx33d openCvCameraMatrix(const mrpt::img::TCamera& camera);

/** Whether OpenCV's pin-hole functions can model the camera's lens:
 * MRPT's `none` and `plumb_bob` models, not `kannala_brandt` (fish-eye,
 * which OpenCV models with its own cv::fisheye functions). */
bool isPinholeModel(const mrpt::img::TCamera& camera);

/** OpenCV's distortion coefficients of a pin-hole camera: k1 k2 p1 p2 k3
 * of TCamera::dist, and k4 k5 k6 (OpenCV's rational model) when any of
 * those is non-zero; none when all are zero. Read whatever the model field
 * says between `none` and `plumb_bob`, as MRPT's own CStereoRectifyMap and
 * projectPoint_with_distortion do: a camera filled by
 * setDistortionParamsVector keeps the model `none`. Throws
 * std::invalid_argument for a model that is not a pin-hole one
 * (isPinholeModel). */
std::vector<double> openCvDistortion(const mrpt::img::TCamera& camera);

/** openCvDistortion(camera) is not empty. */
bool hasLensDistortion(const mrpt::img::TCamera& camera);

/** The pixel of each camera-frame point (x right, y down, z forward) that
 * the camera sees, through its lens; none for a point behind the camera or
 * outside its field of view. The field of view is the image's border
 * undistorted (OpenCV, every coefficient; cv::fisheye for kannala_brandt),
 * and a point is tested against it on the ideal image plane before it is
 * projected: a lens polynomial has a largest image radius, and projecting
 * points beyond it folds them back into the image (k1 = -0.2: a point 60
 * degrees to the side of a camera that sees 41). */
std::vector<std::optional<cv::Point2d>> pixelsInView(
	const std::vector<cv::Point3d>& points, const mrpt::img::TCamera& camera);

}  // namespace lvf::common
