#pragma once
// NCC of one left-image window against the right-image windows along its
// epipolar line (the same row of the rectified pair), computed on demand and
// cached, so that the search, the peak test and the verifications never score
// a column twice. Window means and deviations come precomputed
// (WindowStatistics.h); only the cross term is summed per column. Written by
// hand because OpenCV's matchTemplate (TM_CCOEFF_NORMED) costs 3-4x more
// here: its per-call set-up dominates for one 11x11 window against a strip of
// a few dozen columns.

#include <opencv2/core.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include <vector>

namespace lvf::depth
{
class EpipolarScores
{
   public:
	/** Both images as neighbour pairs (CrossTerms.h); the right one's means
	 * and standard deviations over the (2 half + 1)^2 window (per frame, so
	 * that no score takes a root). */
	EpipolarScores(
		const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, const cv::Mat1f& rightMean,
		const cv::Mat1f& rightStd, int half);

	/** Starts a new left pixel, whose window has this mean and std. */
	void reset(int u, int v, float leftMean, float leftStd);
	/** Scores right columns [x0, x1], clipped to where a window fits. */
	void compute(int x0, int x1);
	/** Score of column x (computed on demand); -2 outside the image.
	 * Inline: the search's peak and uniqueness tests call it for every
	 * column they look at, mostly for scores already there. */
	float at(int x)
	{
		if (x < firstColumn() || x > lastColumn()) return -2.f;
		// A miss scores a few columns around it at once: they are vectorised
		// together for about the cost of one, and callers walk along the line.
		if (std::isnan(m_scores[static_cast<size_t>(x)])) compute(x - kBlock / 2 + 1, x + kBlock / 2);
		return m_scores[static_cast<size_t>(x)];
	}

	/** Calls f(x) for every column x of [lo, hi] that scores above
	 * `floor` and no lower than either neighbour (neighbours outside
	 * [lo, hi] count too; beyond the image they score -2). The uniqueness
	 * tests walk whole lines this way: one compute, then plain reads (at()
	 * tests every column's bounds and state, and those tests cost more than
	 * the comparisons). */
	template <typename F>
	void forEachPeakAbove(int lo, int hi, double floor, F f)
	{
		lo = std::max(lo, firstColumn());
		hi = std::min(hi, lastColumn());
		if (lo > hi) return;
		const float* s = scored(lo - 1, hi + 1);
		for (int x = lo; x <= hi; x++)
		{
			const float here = s[x];
			if (here <= floor) continue;
			const float before = x > firstColumn() ? s[x - 1] : -2.f;
			const float after = x < lastColumn() ? s[x + 1] : -2.f;
			if (before <= here && after <= here) f(x);
		}
	}

	/** The best score of columns [lo, hi] (clipped to the image) and its
	 * column, the first of equals; {-1, -2} if none. */
	std::pair<int, float> best(int lo, int hi)
	{
		lo = std::max(lo, firstColumn());
		hi = std::min(hi, lastColumn());
		const float* s = scored(lo, hi);
		int bestX = -1;
		float bestScore = -2.f;
		for (int x = lo; x <= hi; x++)
			if (s[x] > bestScore) bestScore = s[x], bestX = x;
		return {bestX, bestScore};
	}

	/** Whether any column of [lo, hi] outside [skipLo, skipHi] scores above
	 * `floor`. */
	bool anyAbove(int lo, int hi, int skipLo, int skipHi, double floor)
	{
		lo = std::max(lo, firstColumn());
		hi = std::min(hi, lastColumn());
		const float* s = scored(lo, hi);
		for (int x = lo; x <= hi; x++)
			if ((x < skipLo || x > skipHi) && s[x] > floor) return true;
		return false;
	}

	/** The columns around the peak at `peak` over which the scores descend
	 * from it on both sides (its flanks), looked for no farther than
	 * [lo, hi] (or the peak itself). */
	std::pair<int, int> flanks(int peak, int lo, int hi)
	{
		int first = peak, last = peak;
		while (first - 1 >= std::min(lo, peak) && at(first - 1) < at(first)) first--;
		while (last + 1 <= std::max(hi, peak) && at(last + 1) < at(last)) last++;
		return {first, last};
	}

	int firstColumn() const { return m_half; }
	int lastColumn() const { return m_rightPairs.cols - 1 - m_half; }
	size_t evaluations() const { return m_evaluations; }

   private:
	/** The scores, indexed by column, with [lo, hi] (clipped to the image)
	 * computed. */
	const float* scored(int lo, int hi)
	{
		compute(lo, hi);
		return m_scores.data();
	}

	static constexpr int kBlock = 8;  //!< columns scored together on a miss
	const cv::Mat1i& m_leftPairs;
	const cv::Mat1i& m_rightPairs;
	const cv::Mat1f& m_rightMean;
	const cv::Mat1f& m_rightStd;
	int m_half, m_u = 0, m_v = 0;
	float m_leftMean = 0, m_leftStd = 1;
	std::vector<float> m_scores;  // NaN: not computed yet
	int m_touchedFirst = 0, m_touchedLast = -1;	 // the columns to clear on reset
	/** A stretch known to be scored throughout (the longest one the calls
	 * so far have made), so that the walks along a line scored already do
	 * not test every column's state first. */
	int m_spanFirst = 0, m_spanLast = -1;
	std::vector<int32_t> m_cross;	 // scratch: cross terms of a stretch
	size_t m_evaluations = 0;
};

}  // namespace lvf::depth
