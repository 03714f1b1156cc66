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
	if (matcher == DenseMatcher::SemiGlobal)
	{
		const int block = 5;
		auto sgbm = cv::StereoSGBM::create(
			minDisparity, numDisparities, block, 8 * block * block, 32 * block * block, 1, 63, 10,
			100, 2, cv::StereoSGBM::MODE_SGBM_3WAY);
		sgbm->compute(left, right, raw);
	}
	else
	{
		auto bm = cv::StereoBM::create(numDisparities, 15);
		bm->setMinDisparity(minDisparity);
		bm->setUniquenessRatio(10);
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
