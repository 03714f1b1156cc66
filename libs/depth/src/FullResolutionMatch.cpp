// FocusedEpipolarSearch's match of one pixel at full resolution, and the
// tests every match must pass (the coarse-to-fine match, CoarseToFineMatch.cpp,
// takes the same tests at full resolution): strong enough, a true peak, the
// core window agrees, the model explains the pixel clearly worse, unique
// along the line, found again from the right image, and not the background
// beside an object's silhouette (shifted windows).

#include <lvfusion/depth/EpipolarScores.h>
#include <lvfusion/depth/FocusedEpipolarSearch.h>
#include "AllowedColumns.h"
#include "CoreWindowNcc.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace lvf::depth
{
namespace
{
/** Columns on each side of the model's own disparity that the model check
 * reads: a match nearer than this to it has the model's column on its own
 * peak's flank [px]. */
constexpr int kModelFlank = 2;
}  // namespace

bool FocusedEpipolarSearch::beatsTheRestOfTheLine(
	EpipolarScores& scores, int bestX, float best, int xNear, int xFar) const
{
	// Its own peak's shoulders, which descend from it, do not count.
	scores.compute(xNear, xFar);
	const auto [peakLo, peakHi] = scores.flanks(bestX, xNear, xFar);
	return !scores.anyAbove(xNear, xFar, peakLo, peakHi, best - m_options.uniquenessMargin);
}

bool FocusedEpipolarSearch::findsItsWayBack(
	MatchingLevel& level, int u, int v, int x, int xNear, int xFar) const
{
	// Disparity d pairs left column u' with right column x when
	// u' = x - cxOffset + d. The disparities verified from u, those of right
	// columns [xNear, xFar], are d = u + cxOffset - [xNear, xFar]; from x they
	// reach the left columns u + x - [xFar, xNear].
	const int lo = u + x - xFar, hi = u + x - xNear;
	EpipolarScores& back = level.backward();
	back.reset(x, v, level.rightMean(v, x), std::max(level.rightStd(v, x), 1e-3f));
	const int bestU = back.best(lo, hi).first;
	return std::abs(bestU - u) <= 1;
}

bool FocusedEpipolarSearch::modelExplainsASide(MatchingLevel& full, const PixelQuery& q, int matchX) const
{
	// Shiftable windows (Bobick & Intille 1999): the window moved sideways
	// until the pixel lies on its edge. Beside an object's silhouette the
	// side away from the object holds only the surface behind, which the
	// model explains; on the object, the side away from its edge holds only
	// the object. Whichever explains its better side owns the pixel: a
	// match that the model beats there is the background beside an object
	// (the centred and the core window still reach onto the object from up
	// to half a window away). Only sideways: bearings are what such
	// fattening spoils, and shifted up or down a table top's edge the
	// windows hold a sloping surface that matches nowhere (measured: no
	// fewer phantoms, a bearing of recall lost).
	const int h = full.half;
	const int xModel = static_cast<int>(std::lround(q.column(q.modelDisparity)));
	struct Side
	{
		int shift;
		float mean, deviation;
	};
	std::array<Side, 2> sides;
	size_t sideCount = 0;
	for (const int shift : {-h, h})
	{
		// The shifted window is the one centred half a window to the side,
		// paired at the same disparity half a window to the side.
		const int u = q.u + shift;
		if (u < h || u > full.leftPairs.cols - 1 - h) continue;
		const WindowSums w = leftWindowSums(full, u, q.v, h);
		const float n = static_cast<float>((2 * h + 1) * (2 * h + 1));
		const float mean = static_cast<float>(w.sum) / n;
		const float deviation = std::sqrt(std::max(static_cast<float>(w.squares) / n - mean * mean, 0.f));
		if (deviation > 0) sides[sideCount++] = {shift, mean, deviation};
	}
	// The best of right columns [x0, x1] (as seen from the pixel) over both sides.
	auto bestOfSides = [&](int x0, int x1) {
		float best = -1.f;
		for (size_t k = 0; k < sideCount; k++)
		{
			const Side& side = sides[k];
			EpipolarScores& shifted = full.shifted;
			shifted.reset(q.u + side.shift, q.v, side.mean, side.deviation);
			shifted.compute(x0 + side.shift, x1 + side.shift);
			for (int x = x0; x <= x1; x++) best = std::max(best, shifted.at(x + side.shift));
		}
		return best;
	};
	// The model first: on an object it rarely matches a side, and then the
	// match's sides need no scoring.
	const float model = bestOfSides(xModel - 1, xModel + 1);
	return model >= m_options.acceptNcc && model > bestOfSides(matchX, matchX);
}

bool FocusedEpipolarSearch::passesLocalTests(
	MatchingLevel& full, const PixelQuery& q, int bestX, float best, Match& m) const
{
	EpipolarScores& scores = full.forward;
	m.x = bestX;
	m.score = best;
	if (best < m_options.acceptNcc)
	{
		m.outcome = SearchOutcome::Weak;
		return false;
	}
	// A true peak: both neighbours lower, even if outside the set.
	m.before = scores.at(bestX - 1), m.after = scores.at(bestX + 1);
	if (m.before >= best || m.after >= best)
	{
		m.outcome = SearchOutcome::NotPeak;
		return false;
	}
	// A window centred just beside an object's silhouette holds part of the
	// object and can match at its depth ("foreground fattening", objects up
	// to half a window too wide). The pixel's own neighbourhood, a core
	// window, tells: on the object it matches there, and better than at the
	// model's disparity; on the background beside the object it matches
	// poorly there, or the model (the surface behind) explains it at least
	// as well.
	const int xModel = q.modelDisparity > 0 ? static_cast<int>(std::lround(q.column(q.modelDisparity))) : -1;
	if (m_options.coreWindow > 0)
	{
		const CoreWindowNcc coreWindow(full, q.u, q.v, m_options.coreWindow / 2);
		const float core = coreWindow.at(bestX);
		bool modelExplainsCore = false;
		if (q.modelDisparity > 0 && core >= m_options.coreAcceptNcc)
		{
			// Strictly better: the match's own column may be among these
			// (an obstacle just in front of a far wall lies that close).
			for (int x = xModel - 1; x <= xModel + 1 && !modelExplainsCore; x++)
				modelExplainsCore = coreWindow.at(x) > core;
		}
		if (core < m_options.coreAcceptNcc || modelExplainsCore)
		{
			m.outcome = SearchOutcome::CoreMismatch;
			return false;
		}
	}
	// The laser's model must explain the pixel clearly worse: if the right
	// image matches about as well at the model's own disparity (best of a
	// few columns, for its sub-pixel error), the evidence does not favour an
	// obstacle. Columns on the flanks of the match's own peak do not count:
	// an obstacle less than a couple of pixels of disparity in front of the
	// wall (far away) has the model's column on its flank, and that is the
	// obstacle scoring, not the model.
	if (q.modelDisparity > 0 &&
		!beatsTheRestOfTheLine(scores, bestX, best, xModel - kModelFlank, xModel + kModelFlank))
	{
		m.outcome = SearchOutcome::Ambiguous;
		return false;
	}
	m.outcome = SearchOutcome::Accepted;
	return true;
}

FocusedEpipolarSearch::Match FocusedEpipolarSearch::matchAtFullResolution(
	MatchingLevel& full, const PixelQuery& q) const
{
	// Score the allowed columns, plus some context beyond each bound
	// (column x holds disparity u + cxOffset - x).
	EpipolarScores& scores = full.forward;
	scores.reset(q.u, q.v, q.leftMean, q.leftStd);
	const DisparitySet& set = q.set;
	const int context = m_options.peakContext;
	auto column = [&](double d) { return q.column(d); };
	const auto [xFirst, xLast] = columnSpan(set, column);
	scores.compute(xFirst - context, xLast + context);
	const auto [bestX, best] = bestAllowedColumn(scores, set, column);
	Match m;
	if (bestX < 0 || !passesLocalTests(full, q, bestX, best, m)) return m;
	// Unique within the stretch searched: no other local maximum close to it.
	bool rival = false;
	scores.forEachPeakAbove(
		std::max(xFirst - context, scores.firstColumn()) + 1, std::min(xLast + context, scores.lastColumn()) - 1,
		best - m_options.uniquenessMargin,
		[&, bestColumn = bestX](int x) { rival |= std::abs(x - bestColumn) > 1; });
	if (rival)
	{
		m.outcome = SearchOutcome::Ambiguous;
		return m;
	}
	// Where the criteria cut the true match away (it lies behind the model,
	// or farther than z_max), a side lobe can win inside the set: a
	// candidate must also beat every other peak of the line, from twice
	// z_max to z_min.
	const double fB = q.g.fB();
	const int lineNear = static_cast<int>(std::ceil(q.column(fB / m_options.zMin)));
	const int lineFar = static_cast<int>(std::floor(q.column(fB / (2 * m_options.zMax))));
	if (m_options.verifyFullLine && !beatsTheRestOfTheLine(scores, bestX, best, lineNear, lineFar))
	{
		m.outcome = SearchOutcome::Ambiguous;
		return m;
	}
	// A window that straddles a depth edge or holds only smooth shading can
	// match a wrong place well; matched back from there, the right window
	// then prefers its own true partner over this pixel.
	if (m_options.leftRightCheck && !findsItsWayBack(full, q.u, q.v, bestX, lineNear, lineFar))
		m.outcome = SearchOutcome::LeftRight;
	return m;
}

}  // namespace lvf::depth
