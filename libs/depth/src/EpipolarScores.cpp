#include <lvfusion/depth/EpipolarScores.h>

#include <algorithm>
#include <cmath>
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
	m_u = u;
	m_v = v;
	m_leftMean = leftMean;
	m_leftStd = leftStd;
}

// The cross-term loop is most of the fusion's time. The default x86-64
// target vectorises it 4 floats wide; an AVX2 clone, picked at load time
// where the CPU has AVX2 (a feature test: "arch=..." clones test the CPU
// model and miss newer ones), runs 8 wide. The sums are the same bit for
// bit: for windows up to 15 x 15 (default 11) every product and partial sum
// is an integer below 2^24, which float holds exactly, so the order of the
// additions cannot change them (larger windows may differ in the last bit
// between CPUs). Only this loop is cloned: the score formula after it must
// round the same way everywhere.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define LVF_VECTOR_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define LVF_VECTOR_CLONES
#endif

namespace
{
/** acc[i] = sum over the window of left(u, v) x right(x0 + i, v), i < n.
 * One window element at a time, the innermost loop over independent
 * columns, so that it vectorises (a per-column dot product would be a serial
 * reduction). */
LVF_VECTOR_CLONES
void crossTerms(const cv::Mat1f& left, const cv::Mat1f& right, int u, int v, int x0, int n, int half, float* acc)
{
	for (int i = 0; i < n; i++) acc[i] = 0.f;
	for (int dy = -half; dy <= half; dy++)
	{
		const float* l = left.ptr<float>(v + dy) + u - half;
		const float* r = right.ptr<float>(v + dy) + x0 - half;
		for (int dx = 0; dx <= 2 * half; dx++)
		{
			const float weight = l[dx];
			const float* rr = r + dx;
			for (int i = 0; i < n; i++) acc[i] += weight * rr[i];
		}
	}
}
}  // namespace

void EpipolarScores::compute(int x0, int x1)
{
	x0 = std::max(x0, firstColumn());
	x1 = std::min(x1, lastColumn());
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
	const float area = static_cast<float>((2 * m_half + 1) * (2 * m_half + 1));
	const float* mean = m_rightMean.ptr<float>(m_v);
	const float* deviation = m_rightStd.ptr<float>(m_v);
	// Columns inside the stretch that were scored before get the same score
	// again: cheaper than testing each, and the loop stays branch-free.
	float* scores = m_scores.data();
	const float leftMean = m_leftMean, leftStd = m_leftStd;
	for (int x = x0; x <= x1; x++)
	{
		const float ncc = (acc[x - x0] / area - leftMean * mean[x]) / (leftStd * deviation[x]);
		scores[x] = deviation[x] < kMinRightStd ? -1.f : ncc;
	}
	m_touchedFirst = std::min(m_touchedFirst, x0);
	m_touchedLast = std::max(m_touchedLast, x1);
	m_evaluations += static_cast<size_t>(n);
}

}  // namespace lvf::depth
