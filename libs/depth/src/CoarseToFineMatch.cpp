// FocusedEpipolarSearch::matchCoarseToFine: the same decisions as the
// full-resolution match, with the expensive ones -- the best of the allowed
// stretch, its uniqueness along the whole line, the left-right check -- taken
// on the half-resolution pair, where a window has a quarter of the pixels and
// the line half the columns. The match is then refined at full resolution
// (a few columns around twice the coarse disparity), where the local tests
// and the sub-pixel peak are taken as before.

#include <lvfusion/depth/FocusedEpipolarSearch.h>

#include "AllowedColumns.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lvf::depth
{
namespace
{
/** The coarse level's scores run lower than the full level's threshold
 * would allow for a true match (smoothing, fewer pixels); this much lower
 * still goes on to be judged at full resolution. */
constexpr float kCoarseAcceptSlack = 0.15f;
/** Coarse peaks this close to the best are scored again at full resolution. */
constexpr float kCoarseRivalMargin = 0.2f;
/** Full-resolution columns scored on each side of twice the coarse disparity. */
constexpr int kRefineColumns = 3;
}  // namespace

FocusedEpipolarSearch::Match FocusedEpipolarSearch::matchCoarseToFine(
	MatchingLevel& full, MatchingLevel& coarse, const PixelQuery& q) const
{
	// Coarse pixel i is centred on full pixel 2 i; disparities halve.
	const int uc = q.u / 2, vc = q.v / 2;
	auto coarseColumn = [&](double d) { return uc + 0.5 * (q.g.cxOffset - d); };
	auto fullColumn = [&](int xc) {
		return static_cast<int>(std::lround(q.column(2.0 * (uc + 0.5 * q.g.cxOffset - xc))));
	};
	const DisparitySet& set = q.set;
	EpipolarScores& scores = coarse.forward;
	// (A flat coarse window would divide by zero; the full one has texture.)
	scores.reset(uc, vc, coarse.leftMeanAt(vc, uc), std::max(coarse.leftStdAt(vc, uc), 1e-3f));
	const int context = std::max(2, m_options.peakContext / 2);
	const auto [xFirst, xLast] = columnSpan(set, coarseColumn);
	scores.compute(xFirst - context, xLast + context);
	const auto [bestXc, bestC] = bestAllowedColumn(scores, set, coarseColumn);
	// A stretch narrower than a coarse column: nothing to gain here.
	if (bestXc < 0) return matchAtFullResolution(full, q);
	Match m;
	if (bestC < m_options.acceptNcc - kCoarseAcceptSlack)
	{
		m.outcome = SearchOutcome::Weak;
		return m;
	}
	if (scores.at(bestXc - 1) >= bestC || scores.at(bestXc + 1) >= bestC)
	{
		m.outcome = SearchOutcome::NotPeak;
		return m;
	}
	// Refine: the best allowed column near twice the coarse disparity.
	const int xEstimate = fullColumn(bestXc);
	EpipolarScores& fine = full.forward;
	fine.reset(q.u, q.v, q.leftMean, q.leftStd);
	fine.compute(xEstimate - kRefineColumns, xEstimate + kRefineColumns);
	const auto [bestX, best] = bestAllowedColumn(
		fine, set, [&](double d) { return q.column(d); }, xEstimate - kRefineColumns, xEstimate + kRefineColumns);
	if (bestX < 0)
	{
		m.outcome = SearchOutcome::NotPeak;
		return m;
	}
	if (!passesLocalTests(full, q, bestX, best, m)) return m;
	// Only now, for a match that passed the cheap local tests, the line.
	// Competitors along it (or only along the stretch searched): the other
	// coarse peaks, off the best one's flanks, that come near it. Coarse
	// scores are smoother than full ones, so they are only candidates: each
	// is scored again at full resolution, below, against the refined match.
	const double fB = q.g.fB();
	const int lineNear = m_options.verifyFullLine
		? static_cast<int>(std::ceil(coarseColumn(fB / m_options.zMin)))
		: xFirst - context;
	const int lineFar = m_options.verifyFullLine
		? static_cast<int>(std::floor(coarseColumn(fB / (2 * m_options.zMax))))
		: xLast + context;
	scores.compute(lineNear, lineFar);
	const auto [flankLo, flankHi] = scores.flanks(bestXc, lineNear, lineFar);
	std::vector<int> rivals;  // full-resolution column estimates
	scores.forEachPeakAbove(lineNear, lineFar, bestC - kCoarseRivalMargin, [&, lo = flankLo, hi = flankHi](int x) {
		if (x < lo || x > hi) rivals.push_back(fullColumn(x));
	});
	if (m_options.leftRightCheck && !findsItsWayBack(coarse, uc, vc, bestXc, lineNear, lineFar))
	{
		m.outcome = SearchOutcome::LeftRight;
		return m;
	}
	const auto [peakLo, peakHi] = fine.flanks(bestX, bestX - 2 * kRefineColumns, bestX + 2 * kRefineColumns);
	for (int rival : rivals)
	{
		fine.compute(rival - kRefineColumns, rival + kRefineColumns);
		for (int x = rival - kRefineColumns; x <= rival + kRefineColumns; x++)
			if ((x < peakLo || x > peakHi) && fine.at(x) > best - m_options.uniquenessMargin)
			{
				m.outcome = SearchOutcome::Ambiguous;
				return m;
			}
	}
	return m;
}

}  // namespace lvf::depth
