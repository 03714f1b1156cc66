#include <lvfusion/common/RowBands.h>
#include <lvfusion/common/SlidingWindowRows.h>
#include <lvfusion/depth/WindowStatistics.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lvf::depth
{
namespace
{
void wholeImage(const cv::Mat1f& image, int half, cv::Mat1f& mean, cv::Mat1f& deviation)
{
	const cv::Size window(2 * half + 1, 2 * half + 1);
	cv::blur(image, mean, window);
	// Squares summed by sqrBoxFilter, the rest in place: the temporaries of
	// matrix expressions cost time for the same values (both levels of the
	// pair: 2.3 -> 2.0 ms per box-room frame).
	cv::Mat variance, meanSquared;
	cv::sqrBoxFilter(image, variance, CV_32F, window);
	cv::multiply(mean, mean, meanSquared);
	cv::subtract(variance, meanSquared, variance);
	// Rounding can leave a flat window's variance just below 0.
	cv::max(variance, 0.0, variance);
	cv::sqrt(variance, deviation);
}
}  // namespace

void windowStatistics(const cv::Mat1f& image, int half, RowGrid rows, cv::Mat1f& mean, cv::Mat1f& deviation)
{
	const int width = image.cols, side = 2 * half + 1;
	// Whole grey levels: every column and window sum (of values and of
	// squares) is an integer below 2^24 for windows up to 15 x 15
	// (225 x 255^2), so float holds it exactly, summed in any order.
	constexpr int kExactSide = 15;
	if (rows.all() || side > kExactSide) return wholeImage(image, half, mean, deviation);
	mean.create(image.size());
	deviation.create(image.size());
	// OpenCV's box filters scale the sum by the reciprocal of the area in
	// double and round to float; so do these.
	const double scale = 1.0 / (side * side);
	const size_t n = static_cast<size_t>(width);
	// The grid's first row where a window fits.
	const int start = rows.first >= half ? rows.first : rows.first + (half - rows.first + rows.step - 1) / rows.step * rows.step;
	// Bands of rows on OpenCV's threads, each sliding sums of its own.
	lvf::common::RowBands(start, image.rows - half, rows.step, 4).forEach([&](int, int firstRow, int endRow) {
		std::vector<float> columnSum(n, 0.f), columnSquares(n, 0.f), windowSum(n), windowSquares(n);
		auto addRow = [&](int y, int direction) {
			const float sign = static_cast<float>(direction);
			const float* row = image.ptr<float>(y);
			for (int u = 0; u < width; u++)
			{
				columnSum[size_t(u)] += sign * row[u];
				columnSquares[size_t(u)] += sign * (row[u] * row[u]);
			}
		};
		auto clear = [&] {
			std::fill(columnSum.begin(), columnSum.end(), 0.f);
			std::fill(columnSquares.begin(), columnSquares.end(), 0.f);
		};
		int previous = -1;
		for (int v = firstRow; v < endRow; v += rows.step)
		{
			// The column sums over rows v - half .. v + half, slid down from
			// the previous grid row's where the windows overlap (exact
			// integers: the order of the additions does not matter).
			lvf::common::slideWindowRows(previous, v, half, clear, addRow);
			previous = v;
			// Window sums where a window fits, a column of the window at a
			// time (loops the compiler vectorises).
			const int first = half, last = width - 1 - half;
			std::fill(windowSum.begin(), windowSum.end(), 0.f);
			std::fill(windowSquares.begin(), windowSquares.end(), 0.f);
			for (int k = -half; k <= half; k++)
				for (int u = first; u <= last; u++)
				{
					windowSum[size_t(u)] += columnSum[size_t(u + k)];
					windowSquares[size_t(u)] += columnSquares[size_t(u + k)];
				}
			float* m = mean.ptr<float>(v);
			float* d = deviation.ptr<float>(v);
			for (int u = first; u <= last; u++)
			{
				const float windowMean = static_cast<float>(double(windowSum[size_t(u)]) * scale);
				const float variance = static_cast<float>(double(windowSquares[size_t(u)]) * scale) - windowMean * windowMean;
				m[u] = windowMean;
				d[u] = std::sqrt(std::max(variance, 0.f));
			}
		}
	});
}

}  // namespace lvf::depth
