#include <lvfusion/common/SlidingWindowRows.h>
#include <lvfusion/common/VectorClones.h>
#include <lvfusion/evaluation/GridWindowSums.h>

#include <algorithm>
#include <cassert>
#include <cstring>
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

/** One image row of the three images the sums are taken over. */
struct ImageRow
{
	const uint8_t* left;
	const uint16_t* warped32;
	const uint8_t* bad;
};

/** Adds one image row's values, squares and products to the column sums:
 * 32-bit integers (for windows up to 31 rows, 31 x 8160^2 < 2^31), in one
 * loop GCC vectorises (cloned for AVX2, whose eight-wide 32-bit multiplies
 * the baseline's SSE2 lacks). */
LVF_VECTOR_CLONES void accumulateRow(ImageRow in, int n, int32_t* __restrict l, int32_t* __restrict ll,
	int32_t* __restrict w, int32_t* __restrict ww, int32_t* __restrict lw, int32_t* __restrict unverifiable)
{
	for (int x = 0; x < n; x++)
	{
		const int32_t a = in.left[x], b = in.warped32[x];
		l[x] += a;
		ll[x] += a * a;
		w[x] += b;
		ww[x] += b * b;
		lw[x] += a * b;
		unverifiable[x] += int32_t(in.bad[x] != 0);
	}
}

/** The same for row `out` leaving and row `in` entering, in one pass where
 * a subtraction and an addition were two: the model check's sliding of the
 * sums took 0.30 ms a frame instead of 0.36 (seeded rooms 301-320, timed in
 * lvf-bench). */
LVF_VECTOR_CLONES void exchangeRow(ImageRow out, ImageRow in, int n, int32_t* __restrict l, int32_t* __restrict ll,
	int32_t* __restrict w, int32_t* __restrict ww, int32_t* __restrict lw, int32_t* __restrict unverifiable)
{
	for (int x = 0; x < n; x++)
	{
		const int32_t a = in.left[x], b = in.warped32[x], c = out.left[x], d = out.warped32[x];
		l[x] += a - c;
		ll[x] += a * a - c * c;
		w[x] += b - d;
		ww[x] += b * b - d * d;
		lw[x] += a * b - c * d;
		unverifiable[x] += int32_t(in.bad[x] != 0) - int32_t(out.bad[x] != 0);
	}
}

typedef uint32_t U32x8 __attribute__((vector_size(32)));
typedef int64_t I64x4 __attribute__((vector_size(32)));
typedef int32_t I32x4 __attribute__((vector_size(16)));

/** prefix[0] = 0, prefix[x + 1] = prefix[x] + columns[x], modulo 2^32.
 * Eight at a time: a block's own running sums by three shifted adds, then
 * the total so far added to every lane (a scalar loop waits for each
 * addition; GCC does not vectorise a running sum by itself). Vector
 * extensions GCC (12 on) and Clang share. */
LVF_VECTOR_CLONES void prefixSums32(const int32_t* __restrict columns, int n, uint32_t* __restrict prefix)
{
	const U32x8 zero = {};
	U32x8 total = {};  // every lane: the sum of the columns before this block
	prefix[0] = 0;
	int x = 0;
	for (; x + 8 <= n; x += 8)
	{
		U32x8 v;
		std::memcpy(&v, columns + x, sizeof v);
		v += __builtin_shufflevector(v, zero, 8, 0, 1, 2, 3, 4, 5, 6);
		v += __builtin_shufflevector(v, zero, 8, 8, 0, 1, 2, 3, 4, 5);
		v += __builtin_shufflevector(v, zero, 8, 8, 8, 8, 0, 1, 2, 3);
		v += total;
		std::memcpy(prefix + x + 1, &v, sizeof v);
		total = __builtin_shufflevector(v, v, 7, 7, 7, 7, 7, 7, 7, 7);
	}
	for (uint32_t running = prefix[x]; x < n; x++) prefix[x + 1] = running += static_cast<uint32_t>(columns[x]);
}

/** The same in 64 bits, four at a time (W^2's window sums need them). */
LVF_VECTOR_CLONES void prefixSums64(const int32_t* __restrict columns, int n, int64_t* __restrict prefix)
{
	const I64x4 zero = {};
	I64x4 total = {};
	prefix[0] = 0;
	int x = 0;
	for (; x + 4 <= n; x += 4)
	{
		I32x4 narrow;
		std::memcpy(&narrow, columns + x, sizeof narrow);
		I64x4 v = __builtin_convertvector(narrow, I64x4);
		v += __builtin_shufflevector(v, zero, 4, 0, 1, 2);
		v += __builtin_shufflevector(v, zero, 4, 4, 0, 1);
		v += total;
		std::memcpy(prefix + x + 1, &v, sizeof v);
		total = __builtin_shufflevector(v, v, 3, 3, 3, 3);
	}
	for (int64_t running = prefix[x]; x < n; x++) prefix[x + 1] = running += columns[x];
}
}  // namespace

GridWindowSums::GridWindowSums(
	const cv::Mat1b& left, const cv::Mat1w& warped32, const cv::Mat1b& unverifiable, int half)
	: m_left(left), m_warped32(warped32), m_unverifiable(unverifiable), m_half(half)
{
	assert(left.size() == warped32.size() && left.size() == unverifiable.size());
	// The column sums of W^2 are 32-bit: 31 rows of (32 x 255)^2 fit, 33 do not.
	if (half < 0 || 2 * half + 1 > kMaxWindow)
		throw std::invalid_argument("GridWindowSums: window side " + std::to_string(2 * half + 1) + " outside 1.." + std::to_string(kMaxWindow));
	for (int q = 0; q < kQuantities; q++)
	{
		m_columns[q].assign(static_cast<size_t>(left.cols), 0);
		if (q != WW) m_prefix[q].assign(static_cast<size_t>(left.cols) + 1, 0);
	}
	m_prefixWW.assign(static_cast<size_t>(left.cols) + 1, 0);
}

void GridWindowSums::moveTo(int v)
{
	assert(v - m_half >= 0 && v + m_half < m_left.rows);
	auto c = [&](int q) { return m_columns[q].data(); };
	auto row = [&](int y) {
		return ImageRow{m_left.ptr<uint8_t>(y), m_warped32.ptr<uint16_t>(y), m_unverifiable.ptr<uint8_t>(y)};
	};
	const int n = m_left.cols;
	lvf::common::slideWindowRows(
		m_row, v, m_half, [&] { for (auto& column : m_columns) std::fill(column.begin(), column.end(), 0); },
		[&](int y) { accumulateRow(row(y), n, c(L), c(LL), c(W), c(WW), c(LW), c(Bad)); },
		[&](int out, int in) { exchangeRow(row(out), row(in), n, c(L), c(LL), c(W), c(WW), c(LW), c(Bad)); });
	m_row = v;
	for (int q = 0; q < kQuantities; q++)
		if (q != WW) prefixSums32(m_columns[q].data(), n, m_prefix[q].data());
	prefixSums64(m_columns[WW].data(), n, m_prefixWW.data());
}

GridWindowSums::Sums GridWindowSums::at(int u) const
{
	assert(u - m_half >= 0 && u + m_half < m_left.cols);
	const auto lo = static_cast<size_t>(u - m_half), hi = static_cast<size_t>(u + m_half + 1);
	// The difference of two running sums modulo 2^32 is the window's sum
	// exactly, for it lies in [0, 2^32) (the header).
	auto sum = [&](int q) { return int64_t{static_cast<uint32_t>(m_prefix[q][hi] - m_prefix[q][lo])}; };
	return {sum(L), sum(LL), sum(W), m_prefixWW[hi] - m_prefixWW[lo], sum(LW), sum(Bad)};
}

}  // namespace lvf::evaluation
