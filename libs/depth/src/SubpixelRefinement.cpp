#include "SubpixelRefinement.h"

#include <algorithm>
#include <cmath>

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
}  // namespace

SubpixelRefinement::SubpixelRefinement(int half, double sigma) : m_half(half)
{
	const int side = 2 * half + 1;
	m_weights.resize(size_t(side * side));
	for (int dv = -half; dv <= half; dv++)
		for (int du = -half; du <= half; du++)
		{
			const double w = std::exp(-0.5 * (du * du + dv * dv) / (sigma * sigma));
			m_weights[size_t((dv + half) * side + du + half)] = w;
			m_weightSum += w;
		}
}

double SubpixelRefinement::refine(
	const cv::Mat1f& left, const cv::Mat1f& right, int u, int v, double column, int iterations) const
{
	const int half = m_half, side = 2 * half + 1;
	double x = column;
	for (int it = 0; it < iterations; it++)
	{
		// Every window column shares x's fraction, so one pair of weights
		// interpolates the whole window.
		const int x0 = int(std::floor(x)) - half;
		if (x0 < 1 || x0 + side + 1 >= right.cols) return column;
		const double w1 = x - std::floor(x), w0 = 1 - w1;
		// Weighted sums for the least squares of l ~ a r + b + c g (g: r's
		// gradient; the step is c / a), with b eliminated by centring.
		const double sw = m_weightSum;
		double sr = 0, sg = 0, sl = 0, srr = 0, srg = 0, sgg = 0, srl = 0, sgl = 0;
		const double* weight = m_weights.data();
		for (int dv = -half; dv <= half; dv++)
		{
			const float* l = left[v + dv] + (u - half);
			const float* r = right[v + dv] + x0;
			for (int k = 0; k < side; k++, weight++)
			{
				const double ri = w0 * r[k] + w1 * r[k + 1];
				const double gi = 0.5 * (w0 * (r[k + 1] - r[k - 1]) + w1 * (r[k + 2] - r[k]));
				const double w = *weight, li = l[k];
				sr += w * ri;
				sg += w * gi;
				sl += w * li;
				srr += w * ri * ri;
				srg += w * ri * gi;
				sgg += w * gi * gi;
				srl += w * ri * li;
				sgl += w * gi * li;
			}
		}
		const double crr = srr - sr * sr / sw, crg = srg - sr * sg / sw, cgg = sgg - sg * sg / sw;
		const double crl = srl - sr * sl / sw, cgl = sgl - sg * sl / sw;
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
