#include <lvfusion/common/SlidingWindowRows.h>
#include <lvfusion/common/VectorClones.h>
#include <lvfusion/evaluation/GridWindowSums.h>

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <string>

namespace lvf::evaluation
{
namespace
{
enum Quantity
{
	L,
	LL,
	W,
	WW,
	LW,
	Bad
};

/** Adds (sign +1) or subtracts (-1) one image row's values, squares and
 * products to the column sums: 32-bit integers (for windows up to 31 rows,
 * 31 x 8160^2 < 2^31), in one loop GCC vectorises (cloned for AVX2, whose
 * eight-wide 32-bit multiplies the baseline's SSE2 lacks). */
LVF_VECTOR_CLONES void accumulateRow(int sign,
	const uint8_t* __restrict left, const float* __restrict warped, const uint8_t* __restrict bad, int n,
	int32_t* __restrict l, int32_t* __restrict ll, int32_t* __restrict w, int32_t* __restrict ww,
	int32_t* __restrict lw, int32_t* __restrict unverifiable)
{
	for (int x = 0; x < n; x++)
	{
		// Exact: W is a multiple of 1/32 grey level, times a power of two.
		const int32_t a = left[x], b = static_cast<int32_t>(warped[x] * 32.f);
		l[x] += sign * a;
		ll[x] += sign * a * a;
		w[x] += sign * b;
		ww[x] += sign * b * b;
		lw[x] += sign * a * b;
		unverifiable[x] += sign * int32_t(bad[x] != 0);
	}
}
}  // namespace

GridWindowSums::GridWindowSums(
	const cv::Mat1b& left, const cv::Mat1f& warped, const cv::Mat1b& unverifiable, int half)
	: m_left(left), m_warped(warped), m_unverifiable(unverifiable), m_half(half)
{
	assert(left.size() == warped.size() && left.size() == unverifiable.size());
	// The column sums of W^2 are 32-bit: 31 rows of (32 x 255)^2 fit, 33 do not.
	if (half < 0 || 2 * half + 1 > kMaxWindow)
		throw std::invalid_argument("GridWindowSums: window side " + std::to_string(2 * half + 1) + " outside 1.." + std::to_string(kMaxWindow));
	for (int q = 0; q < kQuantities; q++)
	{
		m_columns[q].assign(static_cast<size_t>(left.cols), 0);
		m_prefix[q].assign(static_cast<size_t>(left.cols) + 1, 0);
	}
}

void GridWindowSums::addRow(int v, int sign)
{
	auto c = [&](int q) { return m_columns[q].data(); };
	const uint8_t* l = m_left.ptr<uint8_t>(v);
	const float* w = m_warped.ptr<float>(v);
	const uint8_t* bad = m_unverifiable.ptr<uint8_t>(v);
	accumulateRow(sign, l, w, bad, m_left.cols, c(L), c(LL), c(W), c(WW), c(LW), c(Bad));
}

void GridWindowSums::moveTo(int v)
{
	assert(v - m_half >= 0 && v + m_half < m_left.rows);
	lvf::common::slideWindowRows(
		m_row, v, m_half, [&] { for (auto& c : m_columns) std::fill(c.begin(), c.end(), 0); },
		[&](int y, int sign) { addRow(y, sign); });
	m_row = v;
	// All six running sums in one pass: six independent chains of additions
	// (one quantity at a time, each addition waited for the one before).
	int64_t running[kQuantities] = {};
	for (size_t x = 0; x < m_columns[0].size(); x++)
		for (int q = 0; q < kQuantities; q++) m_prefix[q][x + 1] = running[q] += m_columns[q][x];
}

GridWindowSums::Sums GridWindowSums::at(int u) const
{
	assert(u - m_half >= 0 && u + m_half < m_left.cols);
	const auto lo = static_cast<size_t>(u - m_half), hi = static_cast<size_t>(u + m_half + 1);
	auto sum = [&](int q) { return m_prefix[q][hi] - m_prefix[q][lo]; };
	return {sum(L), sum(LL), sum(W), sum(WW), sum(LW), sum(Bad)};
}

}  // namespace lvf::evaluation
