#include <lvfusion/depth/CrossTerms.h>
#include <lvfusion/depth/EpipolarScores.h>
#include <lvfusion/common/VectorClones.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace lvf::depth
{
namespace
{
// Right windows flatter than this carry no evidence; their NCC would be
// noise divided by almost nothing.
constexpr float kMinRightStd = 1.0f;  // [grey levels]
constexpr float kNotComputed = std::numeric_limits<float>::quiet_NaN();
/** Columns in the cross terms' vector blocks (CrossTerms.cpp: eight 32-bit sums). */
constexpr int kVectorWidth = 8;
}  // namespace

EpipolarScores::EpipolarScores(
	const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, const cv::Mat1f& rightMean,
	const cv::Mat1f& rightStd, int half)
	: m_leftPairs(leftPairs),
	  m_rightPairs(rightPairs),
	  m_rightMean(rightMean),
	  m_rightStd(rightStd),
	  m_half(half),
	  m_scores(static_cast<size_t>(rightPairs.cols), kNotComputed)
{
}

void EpipolarScores::reset(int u, int v, float leftMean, float leftStd)
{
	if (m_touchedFirst <= m_touchedLast)
		std::fill(m_scores.begin() + m_touchedFirst, m_scores.begin() + m_touchedLast + 1, kNotComputed);
	m_touchedFirst = static_cast<int>(m_scores.size());
	m_touchedLast = -1;
	m_spanFirst = 0;
	m_spanLast = -1;
	m_u = u;
	m_v = v;
	m_leftMean = leftMean;
	m_leftStd = leftStd;
}

namespace
{
/** Eight floats, one AVX2 register (two SSE ones in the default clone).
 * GCC's (and Clang's) vector extension. Loaded and stored with memcpy: no
 * alignment assumed. */
typedef float Floats8 __attribute__((vector_size(32)));
typedef int32_t Ints8 __attribute__((vector_size(32)));

/** scores[i] = NCC of the left window with the right one at column i, from
 * the cross sums and both windows' statistics; -1 where the right window is
 * flat. Eight at a time in explicit vectors (the compiler would not
 * if-convert the flat-window test), the same operations as the scalar tail,
 * cloned for AVX2 (one register; search 9.5-9.8 -> 9.0-9.4 ms per box-room
 * frame). Each lane rounds as the scalar code does: no
 * product may be fused into a sum, so contraction is off (AVX2 alone has no
 * FMA anyway), and the same scores come out on every CPU. */
LVF_VECTOR_CLONES __attribute__((optimize("fp-contract=off")))
void nccScores(
	const int32_t* sums, const float* means, const float* deviations, int n, float area, float leftMean,
	float leftStd, float* scores)
{
	int i = 0;
	for (; i + 8 <= n; i += 8)
	{
		Ints8 integers;
		Floats8 m, d;
		std::memcpy(&integers, sums + i, sizeof integers);
		const Floats8 s = __builtin_convertvector(integers, Floats8);
		std::memcpy(&m, means + i, sizeof m);
		std::memcpy(&d, deviations + i, sizeof d);
		const Floats8 ncc = (s / area - leftMean * m) / (leftStd * d);
		const Ints8 flat = d < kMinRightStd;
		const Floats8 out = Floats8((Ints8(Floats8{} - 1.f) & flat) | (Ints8(ncc) & ~flat));
		std::memcpy(scores + i, &out, sizeof out);
	}
	for (; i < n; i++)
	{
		const float ncc = (static_cast<float>(sums[i]) / area - leftMean * means[i]) / (leftStd * deviations[i]);
		scores[i] = deviations[i] < kMinRightStd ? -1.f : ncc;
	}
}
}  // namespace

void EpipolarScores::compute(int x0, int x1)
{
	x0 = std::max(x0, firstColumn());
	x1 = std::min(x1, lastColumn());
	if (x0 > x1 || (x0 >= m_spanFirst && x1 <= m_spanLast)) return;
	const int askedFirst = x0, askedLast = x1;
	while (x0 <= x1 && !std::isnan(m_scores[static_cast<size_t>(x0)])) x0++;
	while (x1 >= x0 && !std::isnan(m_scores[static_cast<size_t>(x1)])) x1--;
	if (x0 > x1) return;
	// A short stretch would run the cross-term loop without its vector
	// body: widen it to whole vectors (more valid scores, for free).
	const int padded = (x1 - x0 + kVectorWidth) / kVectorWidth * kVectorWidth;
	x1 = std::min(x0 + padded - 1, lastColumn());
	x0 = std::max(x1 - padded + 1, firstColumn());
	const int n = x1 - x0 + 1;
	m_cross.resize(static_cast<size_t>(n));
	int32_t* acc = m_cross.data();
	crossTerms(m_leftPairs, m_rightPairs, m_u, m_v, x0, n, m_half, acc);
	// Columns inside the stretch that were scored before get the same score
	// again: cheaper than testing each, and the loop stays branch-free.
	nccScores(acc, m_rightMean.ptr<float>(m_v) + x0, m_rightStd.ptr<float>(m_v) + x0, n,
		static_cast<float>((2 * m_half + 1) * (2 * m_half + 1)), m_leftMean, m_leftStd, m_scores.data() + x0);
	m_touchedFirst = std::min(m_touchedFirst, x0);
	m_touchedLast = std::max(m_touchedLast, x1);
	// All of [askedFirst, askedLast] and [x0, x1] is scored now, and the
	// two overlap: one stretch, which joins the known one if it touches it.
	const int first = std::min(askedFirst, x0), last = std::max(askedLast, x1);
	if (m_spanFirst > m_spanLast || first > m_spanLast + 1 || last < m_spanFirst - 1)
	{
		if (last - first > m_spanLast - m_spanFirst) m_spanFirst = first, m_spanLast = last;
	}
	else
		m_spanFirst = std::min(m_spanFirst, first), m_spanLast = std::max(m_spanLast, last);
	m_evaluations += static_cast<size_t>(n);
}

}  // namespace lvf::depth
