#include <lvfusion/evaluation/ImageNoise.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace lvf::evaluation
{
double estimateNoiseStd(const cv::Mat1b& image, int rowStep)
{
	if (image.rows < 3 || image.cols < 3) return 0;
	// The 3x3 kernel [1 -2 1; -2 4 -2; 1 -2 1] is [1 -2 1] down times
	// [1 -2 1] across. Written out rather than OpenCV's sepFilter2D, which
	// filters every row where the median reads only every rowStep-th (0.18
	// -> 0.11 ms a 640x480 image coming from memory); on those rows the
	// integers are filter2D's (test_image_noise checks; no border is read).
	const int width = image.cols;
	std::vector<int16_t> down(static_cast<size_t>(width)), response(static_cast<size_t>(width));
	// The response is an integer of at most 16 x 255 in magnitude: its
	// median by a histogram, in one pass.
	std::vector<uint32_t> histogram(16 * 255 + 1, 0);
	size_t n = 0;
	for (int v = 1; v < image.rows - 1; v += std::max(1, rowStep))
	{
		const uint8_t *above = image.ptr<uint8_t>(v - 1), *row = image.ptr<uint8_t>(v), *below = image.ptr<uint8_t>(v + 1);
		for (int u = 0; u < width; u++) down[u] = static_cast<int16_t>(above[u] - 2 * row[u] + below[u]);
		for (int u = 1; u < width - 1; u++)
			response[u] = static_cast<int16_t>(std::abs(down[u - 1] - 2 * down[u] + down[u + 1]));
		for (int u = 1; u < width - 1; u++, n++) histogram[static_cast<size_t>(response[u])]++;
	}
	size_t seen = 0, median = 0;
	while (median < histogram.size() && (seen += histogram[median]) < (n + 1) / 2) median++;
	return 1.4826 * static_cast<double>(median) / 6.0;
}

}  // namespace lvf::evaluation
