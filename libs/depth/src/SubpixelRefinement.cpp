#include "SubpixelRefinement.h"
#include <lvfusion/common/VectorClones.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace lvf::depth
{
namespace
{
/** A Gauss-Newton step moves the column at most this far: the linear
 * interpolation the step's gradient comes from holds within a pixel [px]. */
constexpr double kMaxStep = 0.5;
/** The refinement may move the parabola's column at most this far: beyond it,
 * the search's tests (uniqueness, left-right, core window) were taken at
 * another column [px]. */
constexpr double kMaxMove = 1.0;
/** Steps shorter than this end the iterations [px]. */
constexpr double kConverged = 0.01;
/** The gain a of l = a r + b must be at least this: the right window must
 * correlate positively with the left one (a near zero: no information). */
constexpr double kMinGain = 0.1;

/** Four doubles: one AVX2 register, two SSE2 ones in the baseline clone. */
typedef double Doubles4 __attribute__((vector_size(32)));
typedef uint8_t Bytes4 __attribute__((vector_size(4)));

/** The weighted sums one Gauss-Newton step needs, of the right window
 * interpolated at a column's fraction (r), its gradient along the row (g)
 * and the left window (l). */
struct StepSums
{
	double r, g, rr, rg, gg, rl, gl;
};

/** Those sums over `rows` rows of `paddedSide` columns: `right[row]` points
 * one column before the window's first, and holds paddedSide + 3 readable
 * columns; weights are 0 past the window's side, which zeroes what the
 * padding reads. */
LVF_VECTOR_CLONES StepSums stepSums(
	const uint8_t* const* right, const double* left, const double* weights, int rows, int paddedSide, double w1)
{
	const double w0 = 1 - w1;
	// r, g, rr, rg, gg, rl, gl, each four columns wide. (Vectors stay inside
	// this function: passed or returned they would change the clones' ABI.)
	Doubles4 sums[7] = {};
	for (int row = 0; row < rows; row++)
	{
		const uint8_t* r = right[row];
		for (int k = 0; k < paddedSide; k += 4, left += 4, weights += 4)
		{
			// r[k - 1 .. k + 2] of the window's columns k .. k + 3.
			Bytes4 f[4];
			std::memcpy(f, r + k, sizeof f[0]);
			std::memcpy(f + 1, r + k + 1, sizeof f[0]);
			std::memcpy(f + 2, r + k + 2, sizeof f[0]);
			std::memcpy(f + 3, r + k + 3, sizeof f[0]);
			const Doubles4 before = __builtin_convertvector(f[0], Doubles4), at = __builtin_convertvector(f[1], Doubles4),
						   next = __builtin_convertvector(f[2], Doubles4), after = __builtin_convertvector(f[3], Doubles4);
			Doubles4 w, l;
			std::memcpy(&w, weights, sizeof w);
			std::memcpy(&l, left, sizeof l);
			const Doubles4 ri = w0 * at + w1 * next;
			const Doubles4 gi = 0.5 * (w0 * (next - before) + w1 * (after - at));
			const Doubles4 wr = w * ri, wg = w * gi;
			sums[0] += wr, sums[1] += wg;
			sums[2] += wr * ri, sums[3] += wr * gi, sums[4] += wg * gi;
			sums[5] += wr * l, sums[6] += wg * l;
		}
	}
	double lanes[7][4];
	std::memcpy(lanes, sums, sizeof lanes);
	double total[7];
	for (int i = 0; i < 7; i++) total[i] = (lanes[i][0] + lanes[i][1]) + (lanes[i][2] + lanes[i][3]);
	return {total[0], total[1], total[2], total[3], total[4], total[5], total[6]};
}
}  // namespace

SubpixelRefinement::SubpixelRefinement(int half, double sigma)
	: m_half(half), m_paddedSide((2 * half + 1 + kLanes - 1) / kLanes * kLanes)
{
	const int side = 2 * half + 1;
	if (half < 0 || side > kMaxSide)
		throw std::invalid_argument("SubpixelRefinement: window side " + std::to_string(side) + " outside 1.." +
			std::to_string(kMaxSide));
	m_weights.assign(size_t(side * m_paddedSide), 0.0);
	for (int dv = -half; dv <= half; dv++)
		for (int du = -half; du <= half; du++)
		{
			const double w = std::exp(-0.5 * (du * du + dv * dv) / (sigma * sigma));
			m_weights[size_t((dv + half) * m_paddedSide + du + half)] = w;
			m_weightSum += w;
		}
}

double SubpixelRefinement::refine(
	const cv::Mat1b& left, const cv::Mat1b& right, int u, int v, double column, int iterations) const
{
	if (iterations <= 0) return column;
	const int half = m_half, side = 2 * half + 1;
	// The left window, padded like the weights (what the padding holds is
	// multiplied by a zero weight), and its weighted sum: the same every step.
	std::array<double, kMaxSide * (kMaxSide + kLanes)> leftWindow;
	double sl = 0;
	for (int row = 0; row < side; row++)
	{
		const uint8_t* l = left[v - half + row] + (u - half);
		double* padded = leftWindow.data() + row * m_paddedSide;
		for (int k = 0; k < m_paddedSide; k++)
		{
			padded[k] = k < side ? l[k] : 0.0;
			sl += m_weights[size_t(row * m_paddedSide + k)] * padded[k];
		}
	}
	std::array<const uint8_t*, kMaxSide> rightRows;
	const double sw = m_weightSum;
	double x = column;
	for (int it = 0; it < iterations; it++)
	{
		// Every window column shares x's fraction, so one pair of weights
		// interpolates the whole window. The padded sums read columns
		// x0 - 1 .. x0 + paddedSide + 1.
		const int x0 = int(std::floor(x)) - half;
		if (x0 < 1 || x0 + m_paddedSide + 1 >= right.cols) return column;
		for (int row = 0; row < side; row++) rightRows[size_t(row)] = right[v - half + row] + x0 - 1;
		// Weighted least squares of l ~ a r + b + c g (the step is c / a),
		// b eliminated by centring.
		const StepSums s =
			stepSums(rightRows.data(), leftWindow.data(), m_weights.data(), side, m_paddedSide, x - std::floor(x));
		const double crr = s.rr - s.r * s.r / sw, crg = s.rg - s.r * s.g / sw, cgg = s.gg - s.g * s.g / sw;
		const double crl = s.rl - s.r * sl / sw, cgl = s.gl - s.g * sl / sw;
		const double det = crr * cgg - crg * crg;
		if (!(det > 0)) return column;
		const double gain = (crl * cgg - crg * cgl) / det, c = (crr * cgl - crg * crl) / det;
		if (!(gain >= kMinGain)) return column;
		const double step = std::clamp(c / gain, -kMaxStep, kMaxStep);
		x += step;
		if (std::abs(x - column) > kMaxMove) return column;
		if (std::abs(step) < kConverged) break;
	}
	return x;
}

}  // namespace lvf::depth
