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
	void splitIepf(size_t a, size_t b, size_t cluster, std::vector<Piece>& out) const;

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
	double localSpacing(const Piece& a, const Piece& b) const;

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
	void mergePieces(std::vector<Piece>& pieces, bool smallToo);

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
	void absorbSmallPieces(std::vector<Piece>& pieces, bool keepLeftovers);

	/** Between two touching pieces (of one cluster, or of two adjacent
	 * ones: noise cuts a cluster right at a corner now and then), move the
	 * boundary to where the two lines fit best (least total squared
	 * residual), each keeping two points (a side left with fewer than minPoints is a sliver
	 * of a face, dropped later). IEPF breaks where the point farthest from
	 * the chord happens to be: at a corner with one short leg the chord
	 * runs nearly along the long leg, the distance to it falls off slowly
	 * past the corner, and noise can pick a point several rays off. */
	void refineBoundaries(std::vector<Piece>& pieces) const;

	/** The scan's noise across lines [m], robustly: the median over pieces
	 * of their RMS residual (corrected for the two parameters of a line).
	 * Pieces that still hold a corner are the minority and do not move it. */
	double noiseLevel(const std::vector<Piece>& pieces) const;

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
	void trimEnds(std::vector<Piece>& pieces, bool keep);

	/** The gap between an end point of `p` and the next point in, over
	 * kSamplingGaps times the median of the next 3 gaps further in (0 when
	 * the piece is too short to tell). */
	double isolation(const Piece& p, bool atStart) const;

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
