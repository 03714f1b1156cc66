#pragma once
// The baseline the paper's method is measured against: dense stereo over the
// whole image (OpenCV's StereoSGBM in its 3-way mode, or StereoBM), with a
// disparity range covering [z_min, z_max], turned into the same visual points
// (robot frame, robot height band) that the focused search produces, so both
// feed the same ScanFusion and are scored the same way.

#include <lvfusion/common/HeightBand.h>
#include <lvfusion/depth/FocusedEpipolarSearch.h>

namespace lvf::depth
{
enum class DenseMatcher
{
	SemiGlobal,	 //!< cv::StereoSGBM, MODE_SGBM_3WAY
	Block  //!< cv::StereoBM
};

/** Disparity of every left pixel [px] (< 0 where the matcher found none). */
cv::Mat1f denseDisparity(
	const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& geometry,
	double zMin, DenseMatcher matcher);

/** The pixels of a disparity map as robot-frame points, those in the band,
 * sampled every `stride` pixels like the focused search. */
std::vector<VisualPoint> disparityToPoints(
	const cv::Mat1f& disparity, const lvf::evaluation::RectifiedGeometry& geometry,
	const HeightBand& band, double zMin, double zMax, int stride);

}  // namespace lvf::depth
