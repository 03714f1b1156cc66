// The noise estimate the texture gates are set from (ImageNoise.h): known
// Gaussian noise added to a textured image -- smooth shading, sharp-edged
// patches -- is read back, and the texture itself does not count as noise.

#include <gtest/gtest.h>
#include <lvfusion/evaluation/ImageNoise.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <vector>

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

TEST(ImageNoise, IsTheMedianOfOpenCvsFilterOnTheRowsItReads)
{
	// The estimator filters only the rows it reads, by hand: on those its
	// responses must be filter2D's with the 3x3 kernel, so the estimate is
	// 1.4826 / 6 times their median absolute value (the lower median).
	const cv::Mat1f kernel = (cv::Mat1f(3, 3) << 1, -2, 1, -2, 4, -2, 1, -2, 1);
	cv::Mat1b odd = texturedImage(3.0, 11)(cv::Rect(3, 2, 601, 377)).clone();
	for (const cv::Mat1b& image : {texturedImage(2.0, 5), odd})
		for (const int rowStep : {1, 4, 7})
		{
			cv::Mat1s response;
			cv::filter2D(image, response, CV_16S, kernel);
			std::vector<int> magnitudes;
			for (int v = 1; v < image.rows - 1; v += rowStep)
				for (int u = 1; u < image.cols - 1; u++) magnitudes.push_back(std::abs(response(v, u)));
			const size_t lowerMedian = (magnitudes.size() + 1) / 2 - 1;
			std::nth_element(magnitudes.begin(), magnitudes.begin() + lowerMedian, magnitudes.end());
			EXPECT_DOUBLE_EQ(lvf::evaluation::estimateNoiseStd(image, rowStep), 1.4826 * magnitudes[lowerMedian] / 6.0)
				<< image.cols << "x" << image.rows << ", every " << rowStep << " rows";
		}
}
