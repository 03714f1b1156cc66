#pragma once
// The right-image columns a disparity set covers, for the full- and the
// half-resolution matching alike: each maps a disparity d to its column by
// its own `column(d)` (decreasing in d), and the two share these loops.

#include <lvfusion/depth/DisparityInterval.h>
#include <lvfusion/depth/EpipolarScores.h>

#include <climits>
#include <cmath>
#include <utility>

namespace lvf::depth
{
/** First and last column the set reaches (its largest and smallest disparity). */
template <typename Column>
std::pair<int, int> columnSpan(const DisparitySet& set, Column column)
{
	return {static_cast<int>(std::ceil(column(set[set.size() - 1].hi))),
			static_cast<int>(std::floor(column(set[0].lo)))};
}

/** The best-scoring column whose disparity lies in the set, within
 * [lo, hi] and where a window fits; {-1, -2} if there is none. */
template <typename Column>
std::pair<int, float> bestAllowedColumn(
	EpipolarScores& scores, const DisparitySet& set, Column column, int lo = INT_MIN, int hi = INT_MAX)
{
	int bestX = -1;
	float best = -2.f;
	for (size_t k = 0; k < set.size(); k++)
	{
		const auto [x, score] = scores.best(
			std::max(static_cast<int>(std::ceil(column(set[k].hi))), lo),
			std::min(static_cast<int>(std::floor(column(set[k].lo))), hi));
		if (score > best) best = score, bestX = x;
	}
	return {bestX, best};
}

}  // namespace lvf::depth
