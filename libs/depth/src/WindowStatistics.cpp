#include <lvfusion/common/RowBands.h>
#include <lvfusion/common/SlidingWindowRows.h>
#include <lvfusion/common/VectorClones.h>
#include <lvfusion/depth/WindowStatistics.h>

#include <opencv2/core/hal/hal.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace lvf::depth
{
namespace
{
void wholeImage(const cv::Mat1b& grey, int half, cv::Mat1f& mean, cv::Mat1f& deviation)
{
	cv::Mat1f image;
	grey.convertTo(image, CV_32F);
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

/** Adds an image row to the column sums of values and of squares. */
LVF_VECTOR_CLONES void addColumnSums(
	const uint8_t* __restrict row, int width, float* __restrict sums, float* __restrict squares)
{
	for (int u = 0; u < width; u++)
	{
		const float value = row[u];
		sums[u] += value;
		squares[u] += value * value;
	}
}

/** Swaps row `out` of the column sums for row `in`, in one pass. */
LVF_VECTOR_CLONES void exchangeColumnSums(const uint8_t* __restrict out, const uint8_t* __restrict in, int width,
	float* __restrict sums, float* __restrict squares)
{
	for (int u = 0; u < width; u++)
	{
		const float entering = in[u], leaving = out[u];
		sums[u] += entering - leaving;
		squares[u] += entering * entering - leaving * leaving;
	}
}

/** Window sums at columns half .. width - 1 - half from the column sums, a
 * column of the window at a time (whole passes the compiler vectorises). */
LVF_VECTOR_CLONES void windowSumsOfRow(const float* __restrict columnSums, const float* __restrict columnSquares,
	int half, int width, float* __restrict sums, float* __restrict squares)
{
	const int first = half, last = width - 1 - half;
	std::fill(sums + first, sums + last + 1, 0.f);
	std::fill(squares + first, squares + last + 1, 0.f);
	for (int k = -half; k <= half; k++)
		for (int u = first; u <= last; u++)
		{
			sums[u] += columnSums[u + k];
			squares[u] += columnSquares[u + k];
		}
}

/** A row's means and variances (clamped at 0: rounding can leave a flat
 * window's just below) from its window sums, scaled as OpenCV's box
 * filters scale: by the reciprocal of the area in double, rounded to float. */
LVF_VECTOR_CLONES void meansAndVariances(const float* __restrict sums, const float* __restrict squares, int first,
	int last, double scale, float* __restrict mean, float* __restrict variance)
{
	for (int u = first; u <= last; u++)
	{
		const float windowMean = static_cast<float>(double(sums[u]) * scale);
		mean[u] = windowMean;
		variance[u] = std::max(static_cast<float>(double(squares[u]) * scale) - windowMean * windowMean, 0.f);
	}
}
}  // namespace

void windowStatistics(const cv::Mat1b& image, int half, const RowGrid& rows, cv::Mat1f& mean, cv::Mat1f& deviation)
{
	const int width = image.cols, side = 2 * half + 1;
	// Whole grey levels: every column and window sum (of values and of
	// squares) is an integer below 2^24 for windows up to 15 x 15
	// (225 x 255^2), so float holds it exactly, summed in any order.
	constexpr int kExactSide = 15;
	if (rows.all() || side > kExactSide) return wholeImage(image, half, mean, deviation);
	mean.create(image.size());
	deviation.create(image.size());
	const double scale = 1.0 / (side * side);
	const size_t n = static_cast<size_t>(width);
	// The grid's first row where a window fits.
	const int start = rows.first >= half ? rows.first : rows.first + (half - rows.first + rows.step - 1) / rows.step * rows.step;
	// Bands of rows on OpenCV's threads, each sliding sums of its own.
	lvf::common::RowBands(start, image.rows - half, rows.step, 4).forEach([&](int, int firstRow, int endRow) {
		std::vector<float> columnSum(n, 0.f), columnSquares(n, 0.f), windowSum(n), windowSquares(n);
		auto clear = [&] {
			std::fill(columnSum.begin(), columnSum.end(), 0.f);
			std::fill(columnSquares.begin(), columnSquares.end(), 0.f);
		};
		auto addRow = [&](int y) { addColumnSums(image.ptr<uint8_t>(y), width, columnSum.data(), columnSquares.data()); };
		auto exchangeRows = [&](int out, int in) {
			exchangeColumnSums(image.ptr<uint8_t>(out), image.ptr<uint8_t>(in), width, columnSum.data(), columnSquares.data());
		};
		int previous = -1;
		for (int v = firstRow; v < endRow; v += rows.step)
		{
			if (!rows.isWanted(v)) continue;
			// The column sums over rows v - half .. v + half, slid down from
			// the previous wanted row's where the windows overlap (exact
			// integers: the order of the additions does not matter, and
			// each swap's terms are exact too).
			lvf::common::slideWindowRows(previous, v, half, clear, addRow, exchangeRows);
			previous = v;
			windowSumsOfRow(columnSum.data(), columnSquares.data(), half, width, windowSum.data(), windowSquares.data());
			meansAndVariances(windowSum.data(), windowSquares.data(), half, width - 1 - half, scale, mean.ptr<float>(v), deviation.ptr<float>(v));
			// The deviations by OpenCV's vectorised square root (std::sqrt's
			// errno check keeps GCC from vectorising; IEEE's root is exact
			// either way).
			float* variance = deviation.ptr<float>(v) + half;
			cv::hal::sqrt32f(variance, variance, width - 2 * half);
		}
	});
}

}  // namespace lvf::depth
