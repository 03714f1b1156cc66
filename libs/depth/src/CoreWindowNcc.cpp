#include "CoreWindowNcc.h"

#include <lvfusion/depth/CrossTerms.h>

#include <cmath>

namespace lvf::depth
{
WindowSums leftWindowSums(const MatchingLevel& level, int u, int v, int half)
{
	WindowSums w;
	for (int dy = -half; dy <= half; dy++)
	{
		const int32_t* l = level.leftPairs.ptr<int32_t>(v + dy) + u;
		for (int dx = -half; dx <= half; dx++)
		{
			const int32_t a = pixelOf(l[dx]);
			w.sum += a, w.squares += a * a;
		}
	}
	return w;
}

CoreWindowNcc::CoreWindowNcc(const MatchingLevel& level, int u, int v, int half)
	: m_level(level), m_u(u), m_v(v), m_half(half), m_left(leftWindowSums(level, u, v, half))
{
}

float CoreWindowNcc::at(int x) const
{
	if (x - m_half < 0 || x + m_half >= m_level.rightPairs.cols) return -1.f;
	int32_t sr = 0, srr = 0, slr = 0;
	for (int dy = -m_half; dy <= m_half; dy++)
	{
		const int32_t* l = m_level.leftPairs.ptr<int32_t>(m_v + dy) + m_u;
		const int32_t* r = m_level.rightPairs.ptr<int32_t>(m_v + dy) + x;
		for (int dx = -m_half; dx <= m_half; dx++)
		{
			const int32_t a = pixelOf(l[dx]), b = pixelOf(r[dx]);
			sr += b, srr += b * b, slr += a * b;
		}
	}
	const double n = (2 * m_half + 1) * (2 * m_half + 1);
	const double sl = m_left.sum, sll = m_left.squares;
	const double cov = slr - sl * sr / n, varL = sll - sl * sl / n, varR = srr - double(sr) * sr / n;
	return varL > 0 && varR > 0 ? static_cast<float>(cov / std::sqrt(varL * varR)) : -1.f;
}

}  // namespace lvf::depth
