#include <lvfusion/common/VectorClones.h>
#include <lvfusion/evaluation/GridRowNcc.h>

#include <opencv2/core/hal/hal.hpp>

#include <algorithm>

namespace lvf::evaluation
{
namespace
{
/** Means, variances (clamped at 0), the covariance and the NCC's squared
 * denominator from the window sums; W's come in 1/32 grey levels (its
 * squares in 1/1024): scaling by powers of two is exact. */
LVF_VECTOR_CLONES void moments(int n, double area, const double* __restrict l, const double* __restrict ll,
	const double* __restrict w32, const double* __restrict ww1024, const double* __restrict lw32,
	double* __restrict meanL, double* __restrict varL, double* __restrict varW, double* __restrict covariance,
	double* __restrict denominatorSquared)
{
	for (int i = 0; i < n; i++)
	{
		const double mL = l[i] / area, mW = w32[i] / 32.0 / area;
		meanL[i] = mL;
		varL[i] = std::max(ll[i] / area - mL * mL, 0.0);
		varW[i] = std::max(ww1024[i] / 1024.0 / area - mW * mW, 0.0);
		covariance[i] = lw32[i] / 32.0 / area - mL * mW;
		denominatorSquared[i] = varL[i] * varW[i] + 1e-6;
	}
}

LVF_VECTOR_CLONES void nccFromMoments(int n, double minVarW, const double* __restrict varW,
	const double* __restrict covariance, const double* __restrict denominator, double* __restrict ncc)
{
	// Divided everywhere, then the flat windows set to 0 (the denominator is
	// at least 1e-3): as one loop with a condition GCC does not vectorise it.
	for (int i = 0; i < n; i++) ncc[i] = covariance[i] / denominator[i];
	for (int i = 0; i < n; i++)
		if (varW[i] < minVarW) ncc[i] = 0.0;
}
}  // namespace

void GridRowNcc::compute(const GridWindowSums& sums, int first, int stride, int count)
{
	const auto n = static_cast<size_t>(count);
	for (auto* v : {&m_l, &m_ll, &m_w32, &m_ww1024, &m_lw32, &m_leftMean, &m_leftVariance, &m_warpedVariance,
			 &m_covariance, &m_denominator, &m_leftStd, &m_ncc})
		v->resize(n);
	m_unverifiable.resize(n);
	for (size_t i = 0; i < n; i++)
	{
		const GridWindowSums::Sums w = sums.at(first + int(i) * stride);
		m_l[i] = double(w.l);
		m_ll[i] = double(w.ll);
		m_w32[i] = double(w.w32);
		m_ww1024[i] = double(w.ww1024);
		m_lw32[i] = double(w.lw32);
		m_unverifiable[i] = w.unverifiable;
	}
	moments(count, m_area, m_l.data(), m_ll.data(), m_w32.data(), m_ww1024.data(), m_lw32.data(), m_leftMean.data(),
		m_leftVariance.data(), m_warpedVariance.data(), m_covariance.data(), m_denominator.data());
	// OpenCV's vectorised square roots (std::sqrt's errno check keeps GCC
	// from vectorising; IEEE's root is exact either way).
	cv::hal::sqrt64f(m_denominator.data(), m_denominator.data(), count);
	cv::hal::sqrt64f(m_leftVariance.data(), m_leftStd.data(), count);
	nccFromMoments(count, m_minVariance, m_warpedVariance.data(), m_covariance.data(), m_denominator.data(), m_ncc.data());
}

}  // namespace lvf::evaluation
