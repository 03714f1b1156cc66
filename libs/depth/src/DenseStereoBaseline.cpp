#include <lvfusion/depth/DenseStereoBaseline.h>
#include <opencv2/calib3d.hpp>

#include <Eigen/Dense>

namespace lvf::depth
{
cv::Mat1f denseDisparity(
	const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& g,
	double zMin, DenseMatcher matcher)
{
	// OpenCV's disparity is u_left - u_right = fB / Z - cxOffset: from
	// minDisparity (Z at infinity) up to z_min's, as a multiple of 16.
	const int minDisparity = static_cast<int>(std::floor(-g.cxOffset));
	const double span = g.fB() / zMin - g.cxOffset - minDisparity;
	const int numDisparities = 16 * static_cast<int>(std::ceil(std::max(16.0, span) / 16.0));
	cv::Mat raw;
	// The usual settings of OpenCV's own stereo_match sample and of its
	// documentation (not tuned here): a 5-pixel SGBM block with the
	// smoothness penalties P1 = 8 b^2 and P2 = 32 b^2 of one grey channel, a
	// left-right tolerance of 1 px, uniqueness 10 %, speckles of up to 100
	// pixels varying by at most 2 px removed; BM's 15-pixel block.
	constexpr int kUniquenessPercent = 10;
	if (matcher == DenseMatcher::SemiGlobal)
	{
		constexpr int block = 5, leftRightTolerance = 1, preFilterCap = 63, speckleWindow = 100, speckleRange = 2;
		auto sgbm = cv::StereoSGBM::create(
			minDisparity, numDisparities, block, 8 * block * block, 32 * block * block, leftRightTolerance,
			preFilterCap, kUniquenessPercent, speckleWindow, speckleRange, cv::StereoSGBM::MODE_SGBM_3WAY);
		sgbm->compute(left, right, raw);
	}
	else
	{
		constexpr int block = 15;
		auto bm = cv::StereoBM::create(numDisparities, block);
		bm->setMinDisparity(minDisparity);
		bm->setUniquenessRatio(kUniquenessPercent);
		bm->compute(left, right, raw);
	}
	cv::Mat1f disparity;
	raw.convertTo(disparity, CV_32F, 1.0 / 16.0);  // fixed point, 4 fractional bits
	// Our convention: d = fB / Z; OpenCV's is u_left - u_right.
	disparity += static_cast<float>(g.cxOffset);
	disparity.setTo(-1, raw < (minDisparity * 16));
	return disparity;
}

std::vector<VisualPoint> disparityToPoints(
	const cv::Mat1f& disparity, const lvf::evaluation::RectifiedGeometry& g,
	const HeightBand& band, double zMin, double zMax, int stride)
{
	const Eigen::Vector3d C = g.cameraCentre();
	std::vector<VisualPoint> points;
	for (int v = 0; v < disparity.rows; v += stride)
		for (int u = 0; u < disparity.cols; u += stride)
		{
			const float d = disparity(v, u);
			if (!(d > 0)) continue;
			const double Z = g.fB() / d;
			if (Z < zMin || Z > zMax) continue;
			const Eigen::Vector3d p = C + Z * g.robotRay(u, v);
			if (band.contains(p.z()))
				points.push_back({static_cast<float>(u), static_cast<float>(v), d, 1.f, p});
		}
	return points;
}

}  // namespace lvf::depth
