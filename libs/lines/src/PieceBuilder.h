#pragma once
// Step 2 of the scan -> line segments stage (ScanLineExtractor.h): each
// sphere-of-influence cluster split into straight pieces by iterative
// end-point fit, then the pieces put right -- merged where they are one line
// after all, small ones given to a neighbouring line or dropped, stray end
// points trimmed, boundaries between touching lines moved to where both fit
// best. ScanLineExtractor::extract() runs the passes in order; each says why
// it is needed. Private to the lines library.

#include <lvfusion/lines/LineFit.h>
#include <lvfusion/lines/ScanLineExtractor.h>
#include <lvfusion/lines/ScanPoints.h>
#include <mrpt/core/bits_math.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lvf::lines::detail
{
/** A run of points [first, last] on its way to a segment. Points flagged as
 * outliers inside the run are not part of it. */
struct Piece
{
	size_t first, last, cluster;
	PointMoments moments;  // of its points relative to the sensor
	/** A point trimmed off a line as an outlier: it may join a line
	 * (absorbSmallPieces), but not form one with other small pieces. */
	bool trimmed = false;
	size_t size() const { return moments.n; }
};

class PieceBuilder
{
   public:
	PieceBuilder(const ScanPoints& pts, const ScanLineExtractor::TOptions& o)
		: m_pts(pts),
		  m_o(o),
		  m_minPoints(static_cast<size_t>(o.minPoints)),
		  m_outlier(pts.size(), false)
	{
	}

	/** The scan's noise across lines [m], for the tests that need it.
	 * Outliers are farther from their line than 4 std of it (never below
	 * 1 mm: a noise-free scan still has float ranges); with 5 cm of noise
	 * 1 return in 16000 is called an outlier wrongly. */
	void setNoise(double noise)
	{
		m_noise = noise;
		m_outlierDistance = std::max(4 * noise, 1e-3);
	}

	Eigen::Vector2d rel(size_t k) const { return m_pts.xy[k] - m_pts.origin; }

	PointMoments momentsOf(size_t first, size_t last) const
	{
		PointMoments m;
		for (size_t i = first; i <= last; i++)
			if (!m_outlier[i]) m.add(rel(i));
		return m;
	}

	Piece piece(size_t first, size_t last, size_t cluster) const
	{
		return {first, last, cluster, momentsOf(first, last), false};
	}

	/** Iterative end-point fit on points [a, b]: split at the point
	 * farthest from the chord a-b while it is farther than splitDistance.
	 * The farthest point (a corner, usually) ends the first half; which
	 * half it really belongs to is settled once both lines are known
	 * (refineBoundaries). */
	void splitIepf(size_t a, size_t b, size_t cluster, std::vector<Piece>& out) const
	{
		if (b >= a + 2)
		{
			const Eigen::Vector2d& pa = m_pts.xy[a];
			const Eigen::Vector2d chord = m_pts.xy[b] - pa;
			const double len = chord.norm();
			size_t farthest = a;
			double farthestDist = -1;
			for (size_t k = a + 1; k < b; k++)
			{
				const Eigen::Vector2d v = m_pts.xy[k] - pa;
				// A closed loop (both ends at one place) has no chord: the
				// distance to its end tells it is not straight.
				const double d = len > 1e-9
					? std::abs(chord.x() * v.y() - chord.y() * v.x()) / len
					: v.norm();
				if (d > farthestDist)
				{
					farthestDist = d;
					farthest = k;
				}
			}
			if (farthestDist > m_o.splitDistance)
			{
				splitIepf(a, farthest, cluster, out);
				splitIepf(farthest + 1, b, cluster, out);
				return;
			}
		}
		out.push_back(piece(a, b, cluster));
	}

	/** Consecutive pieces may form one line: same cluster, or facing ends
	 * closer than mergeGap, or than what sampling and noise make of a gap
	 * if more: 3x the spacing of the points either side (a wall seen at
	 * grazing incidence far away has its returns 0.2 m apart) plus 4 std
	 * of the noise of two points (which the sphere-of-influence graph
	 * cuts now and then); but never across more than maxGap. */
	bool adjacent(const Piece& a, const Piece& b) const
	{
		if (a.cluster == b.cluster) return true;
		const double gap = (m_pts.xy[b.first] - m_pts.xy[a.last]).norm();
		if (gap > m_o.maxGap) return false;
		if (gap <= m_o.mergeGap) return true;
		return gap <= kSamplingGaps * localSpacing(a, b) + 4 * M_SQRT2 * m_noise;
	}

	/** Median distance between consecutive points among the last 3 of `a`
	 * and the first 3 of `b` [m]. */
	double localSpacing(const Piece& a, const Piece& b) const
	{
		std::vector<double> d;
		auto steps = [&](size_t from, size_t to, bool forward) {
			size_t k = from;
			for (int i = 0; i < 3; i++)
			{
				const size_t next = forward ? nextPoint(k) : prevPoint(k);
				if (next == npos || (forward ? next > to : next < to)) break;
				d.push_back((m_pts.xy[next] - m_pts.xy[k]).norm());
				k = next;
			}
		};
		steps(a.last, a.first, false);
		steps(b.first, b.last, true);
		if (d.empty()) return 0;
		std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
		return d[d.size() / 2];
	}

	double maxDistance(const LineFit& line, size_t first, size_t last) const
	{
		double d = 0;
		for (size_t i = first; i <= last; i++)
			if (!m_outlier[i]) d = std::max(d, line.distance(rel(i)));
		return d;
	}

	/** Merge adjacent pieces that are one line after all, the best-fitting
	 * pair first, until no pair qualifies. Noise makes IEPF split straight
	 * walls now and then (its test looks at single points); the union's RMS
	 * residual looks at all of them. Two pieces of minPoints or more must
	 * also agree in direction: differ by less than mergeAngleDeg, or by no
	 * more than the noise explains. With 5 cm of noise on rays 2 cm apart
	 * a 0.2 m piece has no direction to speak of, and a fixed angle would
	 * keep such a face in pieces; so the second test asks whether one line
	 * fits both pieces significantly worse than two lines do: the extra
	 * sum of squares over the scan's noise variance is chi-square with 2
	 * degrees of freedom if they are one line, below 13.8 at 99.9%.
	 * And a piece that is its larger neighbour's line plus one stray
	 * return (all its points but one within the outlier distance of that
	 * line) joins it whatever its own direction, the stray becoming an
	 * outlier: one return of a box side seen edge-on, 0.2 m behind the
	 * front face, tilts 4 front returns 2 cm apart (with 5 cm of noise) by
	 * tens of degrees. A real face beside another has most of its points
	 * off the other's line.
	 * A piece smaller than minPoints is no line of its own, and an RMS over
	 * a long union would hide it however far off it is: it only merges
	 * with another small one, and only if every point stays within
	 * splitDistance of the joint line. */
	void mergePieces(std::vector<Piece>& pieces, bool smallToo)
	{
		const double maxAngle = mrpt::DEG2RAD(m_o.mergeAngleDeg);
		for (;;)
		{
			size_t best = pieces.size(), bestStray = npos;
			double bestRms = std::numeric_limits<double>::infinity();
			for (size_t i = 0; i + 1 < pieces.size(); i++)
			{
				const Piece& a = pieces[i];
				const Piece& b = pieces[i + 1];
				const bool smallA = a.size() < m_minPoints, smallB = b.size() < m_minPoints;
				if (smallA != smallB || (smallA && (!smallToo || a.trimmed || b.trimmed)) ||
					!adjacent(a, b))
					continue;
				const LineFit u = fitLine(a.moments + b.moments);
				size_t stray = npos;
				bool one = false;
				if (smallA)
					one = u.rmsResidual < m_o.mergeResidual &&
						maxDistance(u, a.first, b.last) <= m_o.splitDistance;
				else
				{
					const LineFit la = fitLine(a.moments), lb = fitLine(b.moments);
					const double angle =
						std::acos(std::min(1.0, std::abs(la.normal.dot(lb.normal))));
					const double extra = u.sumSquaredResiduals() -
						la.sumSquaredResiduals() - lb.sumSquaredResiduals();
					one = u.rmsResidual < m_o.mergeResidual &&
						(angle < maxAngle || extra < kChiSquare2 * m_noise * m_noise);
					if (!one)
						one = strayOf(a.size() < b.size() ? a : b,
									  a.size() < b.size() ? lb : la, stray);
				}
				double rms = u.rmsResidual;
				if (one && stray != npos)
				{
					PointMoments s;
					s.add(rel(stray));
					rms = fitLine(a.moments + b.moments - s).rmsResidual;
					one = rms < m_o.mergeResidual;
				}
				if (!one || rms >= bestRms) continue;
				best = i;
				bestStray = stray;
				bestRms = rms;
			}
			if (best == pieces.size()) return;
			Piece& a = pieces[best];
			const Piece b = pieces[best + 1];
			a.last = b.last;
			a.moments += b.moments;
			if (bestStray != npos)
			{
				PointMoments s;
				s.add(rel(bestStray));
				a.moments -= s;
				m_outlier[bestStray] = true;
				if (a.first == bestStray) a.first = nextPoint(bestStray);
				if (a.last == bestStray) a.last = prevPoint(bestStray);
			}
			pieces.erase(pieces.begin() + static_cast<std::ptrdiff_t>(best) + 1);
			// Bridging two clusters joins them, for the pieces still to come.
			if (b.cluster != a.cluster)
				for (auto& q : pieces)
					if (q.cluster == b.cluster) q.cluster = a.cluster;
		}
	}

	/** Are all points of `p` but at most one within the outlier distance
	 * of `line`? The one (if any) in `stray`. */
	bool strayOf(const Piece& p, const LineFit& line, size_t& stray) const
	{
		stray = npos;
		for (size_t k = p.first; k <= p.last; k++)
		{
			if (m_outlier[k] || line.distance(rel(k)) <= m_outlierDistance) continue;
			if (stray != npos) return false;
			stray = k;
		}
		return true;
	}

	/** Pieces smaller than minPoints give their points to the neighbouring
	 * lines: each point within splitDistance of the line it would join
	 * joins it. (Noise makes IEPF cut a few points off the end of a wall;
	 * those come back. A lone return off a thin object, or a box side seen
	 * edge-on, does not.) Consecutive small pieces go together, so that an
	 * outlier between a wall and its last returns does not cut them off.
	 * The points before some cut go to the previous line, the rest to the
	 * next; the cut is where the most points find a line. Points that find
	 * none stay a small piece between the two with `keepLeftovers` (small
	 * pieces side by side may still make a line of their own: a short face
	 * that noise split), else they are outliers. */
	void absorbSmallPieces(std::vector<Piece>& pieces, bool keepLeftovers)
	{
		std::vector<Piece> out;
		for (size_t i = 0; i < pieces.size(); i++)
		{
			if (pieces[i].size() >= m_minPoints)
			{
				out.push_back(pieces[i]);
				continue;
			}
			// The run of small pieces [i, e), each adjacent to the next.
			size_t e = i + 1;
			while (e < pieces.size() && pieces[e].size() < m_minPoints &&
				   adjacent(pieces[e - 1], pieces[e]))
				e++;
			Piece* prev = !out.empty() && out.back().size() >= m_minPoints &&
					adjacent(out.back(), pieces[i])
				? &out.back()
				: nullptr;
			Piece* next = e < pieces.size() && pieces[e].size() >= m_minPoints &&
					adjacent(pieces[e - 1], pieces[e])
				? &pieces[e]
				: nullptr;
			std::vector<size_t> idx, from;	// point, and its piece
			for (size_t j = i; j < e; j++)
				for (size_t k = pieces[j].first; k <= pieces[j].last; k++)
					if (!m_outlier[k])
					{
						idx.push_back(k);
						from.push_back(j);
					}
			const size_t m = idx.size();
			const LineFit lp = prev ? fitLine(prev->moments) : LineFit();
			const LineFit ln = next ? fitLine(next->moments) : LineFit();
			auto fits = [&](const LineFit& l, size_t k) {
				return l.distance(rel(k)) <= m_o.splitDistance;
			};
			// cut: idx[0, cut) may join prev, idx[cut, m) may join next.
			size_t bestCut = prev ? m : 0, bestCount = 0;
			for (size_t cut = prev ? m : 0;; cut--)
			{
				size_t count = 0;
				for (size_t j = 0; j < m; j++)
					count += j < cut ? (prev && fits(lp, idx[j])) : (next && fits(ln, idx[j]));
				if (count > bestCount) bestCount = count, bestCut = cut;
				if (cut == 0 || !next) break;
			}
			std::vector<bool> joined(m, false);
			for (size_t j = 0; j < m; j++)
			{
				const size_t k = idx[j];
				if (j < bestCut && prev && fits(lp, k))
				{
					prev->last = k;
					prev->moments.add(rel(k));
					joined[j] = true;
				}
				else if (j >= bestCut && next && fits(ln, k))
				{
					next->first = std::min(next->first, k);
					joined[j] = true;
				}
			}
			// What joined neither: between the two lines' new ends it stays
			// (in the small piece it came from) with keepLeftovers, inside a
			// line's range it is an outlier.
			std::vector<Piece> rest;
			for (size_t j = 0; j < m; j++)
			{
				if (joined[j]) continue;
				const size_t k = idx[j];
				const bool between = (!prev || k > prev->last) && (!next || k < next->first);
				if (!keepLeftovers || !between)
				{
					m_outlier[k] = true;
					continue;
				}
				const Piece& source = pieces[from[j]];
				if (rest.empty() || rest.back().cluster != source.cluster ||
					(j > 0 && from[j - 1] != from[j]))
					rest.push_back({k, k, source.cluster, {}, source.trimmed});
				rest.back().last = k;
				rest.back().moments.add(rel(k));
			}
			if (next) next->moments = momentsOf(next->first, next->last);
			out.insert(out.end(), rest.begin(), rest.end());
			i = e - 1;
		}
		// Between two pieces, points that belong to neither are outliers.
		for (size_t i = 0; i + 1 < out.size(); i++)
			for (size_t k = out[i].last + 1; k < out[i + 1].first; k++) m_outlier[k] = true;
		pieces = std::move(out);
	}

	/** Between two touching pieces (of one cluster, or of two adjacent
	 * ones: noise cuts a cluster right at a corner now and then), move the
	 * boundary to where the two lines fit best (least total squared
	 * residual), each keeping two points (a side left with fewer than minPoints is a sliver
	 * of a face, dropped later). IEPF breaks where the point farthest from
	 * the chord happens to be: at a corner with one short leg the chord
	 * runs nearly along the long leg, the distance to it falls off slowly
	 * past the corner, and noise can pick a point several rays off. */
	void refineBoundaries(std::vector<Piece>& pieces) const
	{
		for (size_t i = 0; i + 1 < pieces.size(); i++)
		{
			Piece& a = pieces[i];
			Piece& b = pieces[i + 1];
			if (!adjacent(a, b) || b.first != nextPoint(a.last)) continue;
			std::vector<size_t> idx;
			for (size_t k = a.first; k <= b.last; k++)
				if (!m_outlier[k]) idx.push_back(k);
			// prefix[j]: moments of idx[0, j).
			std::vector<PointMoments> prefix(idx.size() + 1);
			for (size_t j = 0; j < idx.size(); j++)
			{
				prefix[j + 1] = prefix[j];
				prefix[j + 1].add(rel(idx[j]));
			}
			const PointMoments all = prefix.back();
			auto sse = [](const PointMoments& m) {
				const double r = fitLine(m).rmsResidual;
				return r * r * static_cast<double>(m.n);
			};
			size_t bestCut = a.size();
			double bestCost = std::numeric_limits<double>::infinity();
			for (size_t cut = 2; cut + 2 <= idx.size(); cut++)
			{
				const double cost = sse(prefix[cut]) + sse(all - prefix[cut]);
				if (cost < bestCost) bestCost = cost, bestCut = cut;
			}
			if (bestCut == a.size() || bestCut == 0 || bestCut >= idx.size()) continue;
			a.last = idx[bestCut - 1];
			b.first = idx[bestCut];
			a.moments = momentsOf(a.first, a.last);
			b.moments = momentsOf(b.first, b.last);
		}
	}

	/** The scan's noise across lines [m], robustly: the median over pieces
	 * of their RMS residual (corrected for the two parameters of a line).
	 * Pieces that still hold a corner are the minority and do not move it. */
	double noiseLevel(const std::vector<Piece>& pieces) const
	{
		std::vector<double> rms;
		for (const Piece& p : pieces)
			if (p.size() >= std::max<size_t>(m_minPoints, 3))
			{
				const double n = static_cast<double>(p.size());
				rms.push_back(fitLine(p.moments).rmsResidual * std::sqrt(n / (n - 2)));
			}
		// No piece to tell: assume splitDistance is 3 std, as documented.
		if (rms.empty()) return m_o.splitDistance / 3;
		std::nth_element(rms.begin(), rms.begin() + rms.size() / 2, rms.end());
		return rms[rms.size() / 2];
	}

	/** Takes off end points that are off the line through the rest of
	 * their piece by more than the outlier distance: a return of the next face at a
	 * corner, within splitDistance of the chord, would otherwise tilt a
	 * short segment by a degree or more, or spoil the RMS test that would
	 * merge its piece with the rest of its face. With `keep`, each becomes
	 * a piece of one point (see absorbSmallPieces: the next face may take
	 * it back) and so does an end point farther from the rest than 3x the
	 * spacing of the next points in: the sphere-of-influence graph joins
	 * every point to its nearest neighbour, so a box side seen edge-on
	 * hangs on to the front face by one return 0.3 m away, and 4 returns
	 * 2 cm apart with 5 cm of noise have no direction to tell it is off.
	 * Without `keep`, such points are outliers. A piece may shrink to two
	 * points. */
	void trimEnds(std::vector<Piece>& pieces, bool keep)
	{
		const double threshold = m_outlierDistance;
		std::vector<Piece> out;
		for (Piece p : pieces)
		{
			std::vector<size_t> offStart, offEnd;
			while (p.size() > 2)
			{
				// The worse end first: one bad end tilts the line through the
				// rest, and then the other end looks bad too.
				PointMoments first, last;
				first.add(rel(p.first));
				last.add(rel(p.last));
				double badFirst = fitLine(p.moments - first).distance(rel(p.first)) / threshold;
				double badLast = fitLine(p.moments - last).distance(rel(p.last)) / threshold;
				if (keep)
				{
					badFirst = std::max(badFirst, isolation(p, true));
					badLast = std::max(badLast, isolation(p, false));
				}
				if (std::max(badFirst, badLast) <= 1) break;
				const bool atStart = badFirst >= badLast;
				const size_t k = atStart ? p.first : p.last;
				(atStart ? offStart : offEnd).push_back(k);
				m_outlier[k] = true;
				p.moments -= atStart ? first : last;
				if (atStart)
					p.first = nextPoint(k);
				else
					p.last = prevPoint(k);
			}
			auto single = [&](size_t k) {
				m_outlier[k] = false;
				out.push_back(piece(k, k, p.cluster));
				out.back().trimmed = true;
			};
			if (keep) std::for_each(offStart.begin(), offStart.end(), single);
			out.push_back(p);
			if (keep) std::for_each(offEnd.rbegin(), offEnd.rend(), single);
		}
		pieces = std::move(out);
	}

	/** The gap between an end point of `p` and the next point in, over
	 * kSamplingGaps times the median of the next 3 gaps further in (0 when
	 * the piece is too short to tell). */
	double isolation(const Piece& p, bool atStart) const
	{
		std::vector<size_t> k{atStart ? p.first : p.last};
		while (k.size() < 5)
		{
			const size_t n = atStart ? nextPoint(k.back()) : prevPoint(k.back());
			if (n == npos || (atStart ? n > p.last : n < p.first)) return 0;
			k.push_back(n);
		}
		auto gap = [&](size_t i) { return (m_pts.xy[k[i + 1]] - m_pts.xy[k[i]]).norm(); };
		std::vector<double> inner{gap(1), gap(2), gap(3)};
		std::nth_element(inner.begin(), inner.begin() + 1, inner.end());
		const double spacing = inner[1];
		return spacing > 0 ? gap(0) / (kSamplingGaps * spacing) : 0;
	}

   private:
	static constexpr size_t npos = std::numeric_limits<size_t>::max();
	size_t nextPoint(size_t k) const
	{
		for (k++; k < m_outlier.size(); k++)
			if (!m_outlier[k]) return k;
		return npos;
	}
	size_t prevPoint(size_t k) const
	{
		while (k-- > 0)
			if (!m_outlier[k]) return k;
		return npos;
	}

	/** A gap of up to this many point spacings is sampling, not a gap. */
	static constexpr double kSamplingGaps = 3;
	/** Chi-square with 2 degrees of freedom, 99.9% quantile. */
	static constexpr double kChiSquare2 = 13.8;

	const ScanPoints& m_pts;
	const ScanLineExtractor::TOptions& m_o;
	double m_noise = 0, m_outlierDistance = 1e-3;
	size_t m_minPoints;
	std::vector<bool> m_outlier;
};

}  // namespace lvf::lines::detail
