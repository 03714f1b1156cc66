#pragma once
// Stage 5 (paper §5, §6): visual obstacles meet the laser in its own terms.
// Each visual point in the robot band is projected onto the floor and binned
// by the laser bearing it falls on; per bearing the fused range is the nearer
// of the laser's and the visual one. A bearing's bin is `bin_width_deg` wide
// (or the rays' spacing, if wider), centred on it: with a laser finer than
// that (a Hokuyo's 0.25 degrees) neighbouring bins overlap, so a bearing
// still gathers as many points as on the paper's 1-degree laser. Isolated matches are not trusted: a
// bearing needs `min_points` visual points within `cluster_tolerance` of each
// other before vision may shorten it, and the cluster must straddle the
// bin's own bearing, with a margin (at an obstacle's edge a bin can hold
// points that lie beside its ray, which the ray misses). The range used is the nearest of the
// cluster's points closest to the bin's bearing (the min_points closest,
// and any others near the bearing) that another cluster point supports:
// robust to the odd mismatch and to the noise's near tail, right on slanted
// faces, and at the front edge of surfaces seen from above.
// A bin with too few points of its own may count its neighbours' (a far
// table top gives a point or two a bin). Last, narrow gaps along an
// obstacle's edge are closed (NarrowGapBridging.h).

#include <lvfusion/depth/FocusedEpipolarSearch.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <optional>
#include <vector>

namespace lvf::fusion
{
class ScanFusion
{
   public:
	/** INI section [ScanFusion]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		int minPoints = 3;	//!< visual points needed to trust a bearing
		double clusterTolerance = 0.15;	 //!< they must lie within this range span [m]
		/** ...and straddle the bin's own bearing, give or take this fraction
		 * of a bin; negative: reach past it by that much on both sides.
		 * Matches beside an object's silhouette take its depth for up to
		 * half a window (about 0.6 of a 1-degree bin), so a bin whose ray
		 * just misses the object can see it. Measured with the core window
		 * (seeded rooms 1-6 and 11-16, 24 frames; Middlebury Motorcycle and
		 * Recycle): +0.1: recall 0.867, phantom rate 0.073, Middlebury
		 * recall 29 of 76; 0: 0.858, 0.059, 26 of 76; -0.1: 0.840, 0.050,
		 * 23 of 76. */
		double centreSlack = 0.0;
		/** The range is taken from the min_points points nearest the bin's
		 * bearing and from any others nearer it than this fraction of a bin.
		 * On real images a bin holds dozens of points, and the three nearest
		 * its bearing are often not the obstacle's front. Measured with
		 * range_support (recall / phantom rate, 0 -> 0.15): Middlebury
		 * Motorcycle 0.739 -> 0.826 / 0 both, Recycle 0.868 -> 0.906 / 0.027
		 * both; with the laser slice at 0.15 / 0.25 / 0.35 m instead of 0.30
		 * (lvf-import-middlebury --laser-height) Motorcycle 0.812 / 0.737 /
		 * 0.700 -> 0.938 / 0.842 / 0.700, Recycle 0.950 / 0.913 / 0.863 ->
		 * 0.950 / 0.913 / 0.882, phantoms unchanged. Alone (no support) it
		 * added phantoms on seeded rooms: 0.027 -> 0.032 on 60 of them. */
		double centralShare = 0.15;
		/** The nearest of those points counts only if another point of the
		 * cluster lies within this range of it [m]; 0: off. A point 3 cm
		 * from every other is the near tail of the matching noise (0.1-0.2
		 * m too near at 2-5 m: half the phantom bearings that were not an
		 * obstacle's edge). Measured with central_share 0.15 (recall /
		 * phantom rate, off -> 0.03 m): 60 seeded rooms 0.855 / 0.032 ->
		 * 0.849 / 0.025, rooms 201-230 0.846 / 0.033 -> 0.841 / 0.025,
		 * rooms 1-6 0.912 / 0.023 -> 0.901 / 0.017; 0.05 m: 0.850 / 0.027. */
		double rangeSupport = 0.03;
		/** On a standing surface -- a cluster whose points span more height
		 * than range -- the range moves from that nearest point toward the
		 * median of the points it was chosen from, by at most this much
		 * disparity [px]; 0: the nearest everywhere. A box's face lies at one
		 * range from bottom to top, and its nearest point is the near tail of
		 * the matching noise (0.1-0.2 m too near 4 m out, where a quarter
		 * pixel is 0.1 m). A lying surface, a table top seen from above
		 * (points at one height over a span of range), keeps its nearest
		 * point: its front edge. The bound keeps the move within the noise
		 * of one match: on real, rounded objects the points' heights also
		 * differ in range, and the nearest is the truth (Middlebury's median
		 * range error with the median itself: Motorcycle 0.013 -> 0.022 m,
		 * Recycle 0.035 -> 0.041 m; bounded by 0.25 px, 0.016 and 0.038 m).
		 * A remembered point (no disparity) stays where it is. Measured
		 * 2026-12-08 with lvf-fuse (recalled / phantom bearings, 0 -> 0.25):
		 * seeded rooms 301-340 1610 / 100 -> 1606 / 87, 201-230 1492 / 69 ->
		 * 1495 / 63, 60 rooms (1-6, ..., 91-96) 2594 / 124 -> 2589 / 106,
		 * 401-440 (used for no choice) 1486 / 99 -> 1483 / 90; the variants
		 * in measurements.md, session 55. */
		double standingMedianShift = 0.25;
		/** Gaps in an obstacle's edge at most this wide (arc length) are
		 * closed (NarrowGapBridging.h); 0: off. Measured 2026-12-03 with
		 * lvf-fuse (recall / phantom bearings, off -> 0.15 m): seeded rooms
		 * 1-6 0.891 -> 0.901 / 19 both, 21-26 0.715 -> 0.728, 31-36 0.838 ->
		 * 0.879 / 24 both, corridor desk 0.715 -> 0.770, Middlebury Recycle
		 * 0.585 -> 0.717 / 0 both, box room the same; 0.2 / 0.25 m: rooms 1-6
		 * 20 phantoms, 31-36 26. */
		double bridgeWidth = 0.15;
		/** A bin with fewer than min_points points of its own may count
		 * those of the bins up to this many either side: its range is the
		 * nearest of its own points that has min_points, its own and its
		 * neighbours', within cluster_tolerance behind it, some of them in
		 * a bin on each side; 0: off. A table top 4 m out gives one or two
		 * grid points a bin (a few image rows, every third column).
		 * Measured 2026-12-05 with lvf-fuse (recalled / phantom bearings,
		 * 0 -> 2): seeded rooms 201-230 1469 -> 1478 of 1752 / 69 both,
		 * 301-340 1584 -> 1591 of 1925 / 99 both, 1-6 257 -> 258 of 284 /
		 * 10 both, 60 seeded rooms 2573 -> 2579 of 3031 / 126 both,
		 * corridor desk 161 -> 166 of 200 / 4 both, box room the same.
		 * With the neighbours on one side enough (the cluster spanning the
		 * bin's bearing): box room 2 more phantom bearings at 1.1 m, 60
		 * rooms 1 more. */
		int neighbourBins = 2;
		/** A bearing's bin, centred on it [deg]; at least the rays' spacing.
		 * Every rule above was measured on 1-degree lasers (the paper's SICK
		 * PLS, the simulator's default), where a bin is a ray's own share of
		 * the scan. On a finer laser the same points spread over more rays:
		 * rooms 201-230 with 0.5- and 0.25-degree scans gave recall 0.817
		 * and 0.736 against 0.844 at 1 degree, when each ray's bin was its
		 * own share. */
		double binWidthDeg = 1.0;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;
	};

	ScanFusion() = default;
	explicit ScanFusion(const TOptions& options) : m_options(options) {}

	/** The left-image columns where the search could match at all (a window
	 * fits), and the grid step between searched columns [px]. */
	struct SearchedColumns
	{
		float first = 0, last = 0, step = 1;
	};

	/** Per laser bearing, the robust visual range (+inf where vision found
	 * nothing trustworthy). With `searched`, a cluster that reaches the edge
	 * of the searched columns need not straddle its bin's bearing: the ray
	 * may leave the searched image there, and nothing beyond it is known.
	 * With `bridged`, which bearings' ranges come from a closed gap
	 * (bridge_width) rather than from points on them. */
	std::vector<float> visualRanges(
		const mrpt::obs::CObservation2DRangeScan& laser,
		const std::vector<lvf::depth::VisualPoint>& points,
		std::optional<SearchedColumns> searched = std::nullopt, std::vector<bool>* bridged = nullptr) const;

	/** The laser scan with each bearing shortened to the visual range where
	 * that is nearer; label FUSED. */
	static mrpt::obs::CObservation2DRangeScan::Ptr fuse(
		const mrpt::obs::CObservation2DRangeScan& laser, const std::vector<float>& visual);

	const TOptions& options() const { return m_options; }

   private:
	/** A visual point in a bearing's bin. */
	struct Hit
	{
		float range;
		float offset;  //!< bearing minus the bin's own bearing, in bin widths
		bool atImageEdge;  //!< from the outermost searched columns
		float height;  //!< in the robot frame [m]
		float disparity;  //!< of its match [px]; NaN for a remembered point
	};
	/** A visual point on the laser's plane: its fractional ray index
	 * (rayIndexOf), range, whether it is at the searched image's edge, and
	 * its height before the projection and its match's disparity. */
	struct PlanePoint
	{
		double index;
		float range;
		bool atImageEdge;
		float height, disparity;
	};
	/** The points on the laser's plane, each under the ray its bearing
	 * rounds to (out of the scan's aperture: dropped). */
	static std::vector<std::vector<PlanePoint>> pointsUnderRays(const mrpt::obs::CObservation2DRangeScan& laser,
		const std::vector<lvf::depth::VisualPoint>& points, std::optional<SearchedColumns> searched);
	/** A bin's range from at least min_points points of its own (`hits`,
	 * reordered): the nearest cluster that straddles its bearing (or lies
	 * at the searched image's edge); +inf if none does. */
	float rangeOfOwnCluster(std::vector<Hit>& hits) const;
	/** Into `hits`: the points (in `byRay`, each under the ray it rounds
	 * to) whose bearing lies within `halfWidths` bin widths of ray i's
	 * (from -halfWidths inclusive to +halfWidths exclusive, so that 1-degree
	 * bins of a 1-degree laser part as rounding to the nearest ray does),
	 * with their offsets in bin widths. */
	void hitsAround(const std::vector<std::vector<PlanePoint>>& byRay, size_t i, double binRays, double halfWidths,
		std::vector<Hit>& hits) const;
	/** The range of a bin's cluster [first, last) along the bin's own ray
	 * (reorders the cluster). */
	float rangeAlongTheRay(std::vector<Hit>::iterator first, std::vector<Hit>::iterator last) const;
	/** A bin's range from its own few points with those of the
	 * neighbour_bins bin widths on each side (`around`, the bin's own
	 * included); +inf if they make no cluster over its bearing. */
	float rangeWithNeighbours(const std::vector<Hit>& own, const std::vector<Hit>& around) const;

	TOptions m_options;
};

}  // namespace lvf::fusion
