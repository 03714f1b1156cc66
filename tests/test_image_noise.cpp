// The noise estimate the texture gates are set from (ImageNoise.h): known
// Gaussian noise added to a textured image -- smooth shading, sharp-edged
// patches -- is read back, and the texture itself does not count as noise.

#include <gtest/gtest.h>
#include <lvfusion/evaluation/ImageNoise.h>
#include <opencv2/imgproc.hpp>

#include <cmath>
#include <iostream>

namespace
{
/** 640 x 480: shading of +-60 grey levels and dark and bright rectangles
 * with sharp edges, plus iid Gaussian noise of std `sigma`, rounded. */
cv::Mat1b texturedImage(double sigma, uint64 seed)
{
	cv::Mat1f image(480, 640);
	for (int v = 0; v < image.rows; v++)
		for (int u = 0; u < image.cols; u++)
			image(v, u) = float(128 + 60 * std::sin(2 * M_PI * u / 40.0) * std::cos(2 * M_PI * v / 30.0));
	for (int k = 0; k < 12; k++)
		cv::rectangle(image, cv::Rect(40 + 45 * k, 30 + 30 * (k % 5), 30, 50), cv::Scalar(k % 2 ? 230 : 20), cv::FILLED);
	cv::Mat1f noise(image.size());
	cv::RNG rng(seed);
	rng.fill(noise, cv::RNG::NORMAL, 0, sigma);
	cv::Mat1b out;
	cv::Mat1f(image + noise).convertTo(out, CV_8U);
	return out;
}
}  // namespace

TEST(ImageNoise, ReadsBackTheNoiseAddedToATexturedImage)
{
	for (const double sigma : {1.0, 2.0, 4.0})
	{
		// Rounding to grey levels adds uniform noise of variance 1/12.
		const double expected = std::sqrt(sigma * sigma + 1.0 / 12);
		const double estimate = lvf::evaluation::estimateNoiseStd(texturedImage(sigma, 7));
		std::cout << "noise std " << sigma << ": estimated " << estimate << " (expected " << expected << ")\n";
		EXPECT_NEAR(estimate, expected, 0.12 * expected) << "sigma " << sigma;
	}
}

TEST(ImageNoise, TextureWithoutNoiseIsNotNoise)
{
	// Shading and edges alone: well under one grey level.
	EXPECT_LT(lvf::evaluation::estimateNoiseStd(texturedImage(0.0, 7)), 0.5);
	EXPECT_EQ(lvf::evaluation::estimateNoiseStd(cv::Mat1b(100, 100, uint8_t(90))), 0.0);
}
