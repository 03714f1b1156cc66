#pragma once
// The right image warped by the laser's model into the left view (stage 3,
// paper §4): where the model is right, the warped image is the left one.

#include <lvfusion/evaluation/RectifiedStereo.h>
#include <opencv2/core.hpp>

namespace lvf::evaluation
{
/** The right image resampled where the model sends each left pixel (its
 * row, `modelDisparity` to the left: column u + cxOffset - d), in 1/32
 * grey levels (`warped32`, whole numbers 0 .. 8160), and the
 * pixels where that cannot be done (255: no model surface, the column
 * leaves the right image, or, with `rightNotImaged` (RectificationEffects),
 * either of the two columns around it is a pixel rectification filled from
 * outside the camera's image: a black corner's edge is texture no camera
 * saw).
 *
 * The values are 32 times cv::remap's (INTER_LINEAR, BORDER_CONSTANT 0)
 * with maps x = u + cxOffset - d, y = v, exactly (test_model_evaluation
 * compares them): the column rounded to 1/32 px as remap rounds it, its two
 * neighbours weighted k / 32 and 1 - k / 32 as remap's table weights them,
 * so that remap's float values are whole multiples of 1/32. Kept as 16-bit
 * integers: the model check's window sums are integers (GridWindowSums.h),
 * and the image is half the bytes of remap's floats. Written by hand
 * because the warp moves pixels along rows only: remap's two-dimensional
 * interpolation and the two float maps it needs took 1.5 ms of a 640x480
 * frame, this 0.65 one column at a time and 0.23 with AVX2 gathers. */
void warpByModel(
	const cv::Mat1b& right, const cv::Mat1f& modelDisparity, const RectifiedGeometry& geometry,
	cv::Mat1w& warped32, cv::Mat1b& unverifiable, const cv::Mat1b& rightNotImaged = {});

}  // namespace lvf::evaluation
