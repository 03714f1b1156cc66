// The dense baselines lvf-bench compares the fusion with
// (DenseStereoBaseline.h), against analytic disparities: a textured plane
// at a known depth, its right image the left one shifted as a rectified rig
// sees it, with and without a principal-point offset between the cameras
// (Middlebury's doffs, where OpenCV's disparity u_left - u_right is fB / Z
// minus that offset).

#include <gtest/gtest.h>
#include <lvfusion/depth/DenseStereoBaseline.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <vector>

using lvf::depth::DenseMatcher;

namespace
{
lvf::evaluation::RectifiedGeometry rig(double cxOffset)
{
	lvf::evaluation::RectifiedGeometry g;
	g.size = cv::Size(640, 480);
	g.f = 500;
	g.cx = 319.5;
	g.cy = 239.5;
	g.cxOffset = cxOffset;
	g.baseline = 0.2;  // fB = 100 px m
	return g;
}

/** Smoothed random texture, the same every run. */
cv::Mat1b texture(cv::Size size)
{
	cv::Mat1f noise(size);
	cv::RNG rng(7);
	rng.fill(noise, cv::RNG::UNIFORM, 0, 255);
	cv::GaussianBlur(noise, noise, cv::Size(0, 0), 1.2);
	cv::Mat1b out;
	cv::normalize(noise, noise, 0, 255, cv::NORM_MINMAX);
	noise.convertTo(out, CV_8U);
	return out;
}

/** The median disparity (d = fB / Z) the matcher gives the image's centre
 * half, and the share of those pixels it gave one. */
std::pair<double, double> centreDisparity(const cv::Mat1f& d)
{
	std::vector<float> found;
	const cv::Rect centre(d.cols / 4, d.rows / 4, d.cols / 2, d.rows / 2);
	for (int v = centre.y; v < centre.br().y; v++)
		for (int u = centre.x; u < centre.br().x; u++)
			if (d(v, u) > 0) found.push_back(d(v, u));
	if (found.empty()) return {0, 0};
	std::nth_element(found.begin(), found.begin() + long(found.size() / 2), found.end());
	return {found[found.size() / 2], double(found.size()) / centre.area()};
}
}  // namespace

TEST(DenseStereoBaseline, CoversTheDisparitiesDownToZMinWhateverThePrincipalPointOffset)
{
	// z_min 1.5 m: d up to 66.7 px. The plane at 100 / 64 = 1.5625 m, just
	// beyond it: d = 64, the right image shifted by 64 - cxOffset pixels.
	const double zMin = 1.5, d = 64;
	for (const double cxOffset : {0.0, 32.0})
	{
		const auto g = rig(cxOffset);
		const cv::Mat1b left = texture(g.size);
		const int shift = static_cast<int>(d - cxOffset);
		cv::Mat1b right(g.size, uint8_t(0));
		left.colRange(shift, g.size.width).copyTo(right.colRange(0, g.size.width - shift));
		for (const auto matcher : {DenseMatcher::SemiGlobal, DenseMatcher::Block})
		{
			const auto [median, share] = centreDisparity(lvf::depth::denseDisparity(left, right, g, zMin, matcher));
			EXPECT_NEAR(median, d, 0.25) << "cxOffset " << cxOffset << ", matcher " << int(matcher);
			EXPECT_GT(share, 0.9) << "cxOffset " << cxOffset << ", matcher " << int(matcher);
		}
	}
}
