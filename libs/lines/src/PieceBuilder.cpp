// PieceBuilder's passes (PieceBuilder.h says what each is for).
#include "PieceBuilder.h"

#include <lvfusion/common/Medians.h>

namespace lvf::lines::detail
{
void PieceBuilder::splitIepf(size_t a, size_t b, size_t cluster, std::vector<Piece>& out) const
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

double PieceBuilder::localSpacing(const Piece& a, const Piece& b) const
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
	return lvf::common::upperMedian(d, 0.0);
}

void PieceBuilder::mergePieces(std::vector<Piece>& pieces, bool smallToo)
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

void PieceBuilder::absorbSmallPieces(std::vector<Piece>& pieces, bool keepLeftovers)
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

void PieceBuilder::refineBoundaries(std::vector<Piece>& pieces) const
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

double PieceBuilder::noiseLevel(const std::vector<Piece>& pieces) const
{
	std::vector<double> rms;
	for (const Piece& p : pieces)
		if (p.size() >= std::max<size_t>(m_minPoints, 3))
		{
			const double n = static_cast<double>(p.size());
			rms.push_back(fitLine(p.moments).rmsResidual * std::sqrt(n / (n - 2)));
		}
	// No piece to tell: assume splitDistance is 3 std, as documented.
	return lvf::common::upperMedian(rms, m_o.splitDistance / 3);
}

void PieceBuilder::trimEnds(std::vector<Piece>& pieces, bool keep)
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

double PieceBuilder::isolation(const Piece& p, bool atStart) const
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

}  // namespace lvf::lines::detail
