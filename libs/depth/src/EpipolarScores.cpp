#include <lvfusion/depth/EpipolarScores.h>

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
/** Floats in the widest vector the cross-term loop is built for (AVX2). */
constexpr int kVectorWidth = 8;
}  // namespace

EpipolarScores::EpipolarScores(
	const cv::Mat1f& left, const cv::Mat1f& right, const cv::Mat1f& rightMean,
	const cv::Mat1f& rightStd, int half)
	: m_left(left),
	  m_right(right),
	  m_rightMean(rightMean),
	  m_rightStd(rightStd),
	  m_half(half),
	  m_scores(static_cast<size_t>(right.cols), kNotComputed)
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

// The cross-term loop is most of the search's time. The default x86-64
// target runs its 8-float vectors as pairs of SSE registers; an AVX2 clone,
// picked at load time where the CPU has AVX2 (a feature test: "arch=..."
// clones test the CPU model and miss newer ones), as single registers. The
// sums are the same bit for bit: both levels of the pair hold whole grey
// levels (MatchingLevel rounds the half-resolution one), so for windows up
// to 15 x 15 (default 11) every product and partial sum is an integer below
// 2^24, which float holds exactly, and neither the order of the additions
// (partial sums in chains, below) nor the CPU can change them. Only this
// loop is cloned: the score formula after it must round the same way
// everywhere.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define LVF_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define LVF_VECTOR_CLONES
#endif

namespace
{
// Inlined into each clone of crossTerms, so that it is built for each target.
#define LVF_ALWAYS_INLINE inline __attribute__((always_inline))

/** Eight floats, one AVX2 register (two SSE ones in the default clone).
 * GCC's (and Clang's) vector extension: left to itself the compiler
 * vectorised the wrong loop (across the window's columns, with shuffles).
 * Loaded and stored with memcpy: no alignment assumed. */
typedef float Floats8 __attribute__((vector_size(32)));
/** Four floats, one SSE register, and their comparison masks: the
 * default target's own width (wider vectors' masks were scalarised). */
typedef float Floats4 __attribute__((vector_size(16)));
typedef int32_t Ints4 __attribute__((vector_size(16)));
typedef int32_t Ints8 __attribute__((vector_size(32)));

/** out[k] = sum over the window of left(u, v) x right(x + k, v), k < 8 V,
 * for a window of half side Half (a template argument, so that the loop
 * along the window's row unrolls and every partial sum gets a register).
 * The sums stay in registers for the whole window: summed into memory,
 * every product cost a load and a store of its sum besides its own load.
 * Each 8-column block keeps several partial sums, one per column of the
 * window by turns, so that several additions are in flight at once: with
 * one sum per block every product waited for the one before (4 cycles),
 * and the 8-column blocks -- every full-resolution refinement -- ran at a
 * quarter of the adder's rate. */
template <int V, int Half>
LVF_ALWAYS_INLINE void crossBlock(const cv::Mat1f& left, const cv::Mat1f& right, int u, int v, int x, float* out)
{
	constexpr int Width = 2 * Half + 1;
	constexpr int Chains = std::min(Width, 8 / V);
	Floats8 sums[Chains][V] = {};
	for (int dy = -Half; dy <= Half; dy++)
	{
		const float* l = left.ptr<float>(v + dy) + u - Half;
		const float* r = right.ptr<float>(v + dy) + x - Half;
#pragma GCC unroll 16
		for (int dx = 0; dx < Width; dx++)
		{
			const Floats8 weight = Floats8{} + l[dx];
			for (int j = 0; j < V; j++)
			{
				Floats8 column;
				std::memcpy(&column, r + dx + 8 * j, sizeof column);
				sums[dx % Chains][j] += weight * column;
			}
		}
	}
	for (int c = 1; c < Chains; c++)
		for (int j = 0; j < V; j++) sums[0][j] += sums[c][j];
	std::memcpy(out, sums[0], sizeof sums[0]);
}

/** The same for one column (the stretch's tail). */
LVF_ALWAYS_INLINE float crossColumn(const cv::Mat1f& left, const cv::Mat1f& right, int u, int v, int x, int half)
{
	float sum = 0;
	for (int dy = -half; dy <= half; dy++)
	{
		const float* l = left.ptr<float>(v + dy) + u - half;
		const float* r = right.ptr<float>(v + dy) + x - half;
		for (int dx = 0; dx <= 2 * half; dx++) sum += l[dx] * r[dx];
	}
	return sum;
}

/** acc[i] = sum over the window of left(u, v) x right(x0 + i, v), i < n:
 * blocks of 32, 16 and 8 columns, single columns for the rest. */
template <int Half>
LVF_ALWAYS_INLINE void crossTermsOf(const cv::Mat1f& left, const cv::Mat1f& right, int u, int v, int x0, int n, float* acc)
{
	int i = 0;
	for (; i + 32 <= n; i += 32) crossBlock<4, Half>(left, right, u, v, x0 + i, acc + i);
	for (; i + 16 <= n; i += 16) crossBlock<2, Half>(left, right, u, v, x0 + i, acc + i);
	for (; i + 8 <= n; i += 8) crossBlock<1, Half>(left, right, u, v, x0 + i, acc + i);
	for (; i < n; i++) acc[i] = crossColumn(left, right, u, v, x0 + i, Half);
}

LVF_VECTOR_CLONES
void crossTerms(const cv::Mat1f& left, const cv::Mat1f& right, int u, int v, int x0, int n, int half, float* acc)
{
	switch (half)
	{
		case 1: return crossTermsOf<1>(left, right, u, v, x0, n, acc);
		case 2: return crossTermsOf<2>(left, right, u, v, x0, n, acc);
		case 3: return crossTermsOf<3>(left, right, u, v, x0, n, acc);
		case 4: return crossTermsOf<4>(left, right, u, v, x0, n, acc);
		case 5: return crossTermsOf<5>(left, right, u, v, x0, n, acc);
		case 6: return crossTermsOf<6>(left, right, u, v, x0, n, acc);
		case 7: return crossTermsOf<7>(left, right, u, v, x0, n, acc);
		default:  // windows above 15 x 15 (not exact in float anyway): a column at a time
			for (int i = 0; i < n; i++) acc[i] = crossColumn(left, right, u, v, x0 + i, half);
	}
}

/** scores[i] = NCC of the left window with the right one at column i, from
 * the cross sums and both windows' statistics; -1 where the right window is
 * flat. Eight at a time in explicit vectors (the compiler would not
 * if-convert the flat-window test), the same operations as the scalar tail,
 * cloned like the cross terms (AVX2: one register; search 9.5-9.8 -> 9.0-9.4
 * ms per box-room frame). Each lane rounds as the scalar code does: no
 * product may be fused into a sum, so contraction is off (AVX2 alone has no
 * FMA anyway), and the same scores come out on every CPU. */
LVF_VECTOR_CLONES __attribute__((optimize("fp-contract=off")))
void nccScores(
	const float* sums, const float* means, const float* deviations, int n, float area, float leftMean,
	float leftStd, float* scores)
{
	int i = 0;
	for (; i + 8 <= n; i += 8)
	{
		Floats8 s, m, d;
		std::memcpy(&s, sums + i, sizeof s);
		std::memcpy(&m, means + i, sizeof m);
		std::memcpy(&d, deviations + i, sizeof d);
		const Floats8 ncc = (s / area - leftMean * m) / (leftStd * d);
		const Ints8 flat = d < kMinRightStd;
		const Floats8 out = Floats8((Ints8(Floats8{} - 1.f) & flat) | (Ints8(ncc) & ~flat));
		std::memcpy(scores + i, &out, sizeof out);
	}
	for (; i < n; i++)
	{
		const float ncc = (sums[i] / area - leftMean * means[i]) / (leftStd * deviations[i]);
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
	float* acc = m_cross.data();
	crossTerms(m_left, m_right, m_u, m_v, x0, n, m_half, acc);
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
