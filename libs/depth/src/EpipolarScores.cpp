#include <lvfusion/depth/EpipolarScores.h>

#include <cmath>
#include <limits>

namespace lvf::depth
{
namespace
{
// Right windows flatter than this (std below 1 grey level) carry no
// evidence; their NCC would be noise divided by almost nothing.
constexpr float kMinRightVariance = 1.0f;
constexpr float kNotComputed = std::numeric_limits<float>::quiet_NaN();
}  // namespace

EpipolarScores::EpipolarScores(
	const cv::Mat1f& left, const cv::Mat1f& right, const cv::Mat1f& rightMean,
	const cv::Mat1f& rightVariance, int half)
	: m_left(left),
	  m_right(right),
	  m_rightMean(rightMean),
	  m_rightVariance(rightVariance),
	  m_half(half),
	  m_scores(static_cast<size_t>(right.cols), kNotComputed)
{
}

void EpipolarScores::reset(int u, int v, float leftMean, float leftStd)
{
	for (int x : m_touched) m_scores[static_cast<size_t>(x)] = kNotComputed;
	m_touched.clear();
	m_u = u;
	m_v = v;
	m_leftMean = leftMean;
	m_leftStd = leftStd;
}

void EpipolarScores::compute(int x0, int x1)
{
	x0 = std::max(x0, firstColumn());
	x1 = std::min(x1, lastColumn());
	while (x0 <= x1 && !std::isnan(m_scores[static_cast<size_t>(x0)])) x0++;
	while (x1 >= x0 && !std::isnan(m_scores[static_cast<size_t>(x1)])) x1--;
	if (x0 > x1) return;
	// The cross term for all columns at once, one window element at a time:
	// the innermost loop runs over independent columns, so the compiler
	// vectorises it (a per-column dot product would be a serial reduction).
	const int n = x1 - x0 + 1;
	m_cross.assign(static_cast<size_t>(n), 0.f);
	float* acc = m_cross.data();
	for (int dy = -m_half; dy <= m_half; dy++)
	{
		const float* l = m_left.ptr<float>(m_v + dy) + m_u - m_half;
		const float* r = m_right.ptr<float>(m_v + dy) + x0 - m_half;
		for (int dx = 0; dx <= 2 * m_half; dx++)
		{
			const float weight = l[dx];
			const float* rr = r + dx;
			for (int i = 0; i < n; i++) acc[i] += weight * rr[i];
		}
	}
	const float area = static_cast<float>((2 * m_half + 1) * (2 * m_half + 1));
	const float* mean = m_rightMean.ptr<float>(m_v);
	const float* variance = m_rightVariance.ptr<float>(m_v);
	for (int x = x0; x <= x1; x++)
	{
		float& s = m_scores[static_cast<size_t>(x)];
		if (std::isnan(s)) m_touched.push_back(x);
		s = variance[x] < kMinRightVariance
			? -1.f
			: (acc[x - x0] / area - m_leftMean * mean[x]) / (m_leftStd * std::sqrt(variance[x]));
	}
	m_evaluations += static_cast<size_t>(n);
}

float EpipolarScores::at(int x)
{
	if (x < firstColumn() || x > lastColumn()) return -2.f;
	if (std::isnan(m_scores[static_cast<size_t>(x)])) compute(x, x);
	return m_scores[static_cast<size_t>(x)];
}

}  // namespace lvf::depth
