#pragma once
// Stage 1 of the method (paper §3, DESIGN.md): a 2D scan to line segments, in
// the paper's three steps:
//  1. clusters of connected points by the sphere-of-influence graph
//     (Toussaint): a point's radius of influence is the distance to its
//     nearest neighbour (but at least about the range noise), two points are
//     connected when their spheres touch;
//  2. each cluster split into straight pieces by iterative end-point fit
//     (IEPF), then adjacent pieces that are one line after all merged;
//  3. each piece refitted by total least squares, its endpoints the first and
//     last point projected onto the line; short or sparse pieces dropped.
// With the paper's 5 cm of range noise and rays 2-7 cm apart, step 2 also
// has to decide what a handful of points is: pieces under minPoints give
// their points to a neighbouring line they fit or are dropped, single
// returns far off their line are outliers, and the boundary between two
// lines is put where they fit best (src/PieceBuilder.h says why for each).

#include <lvfusion/lines/LineSegment.h>
#include <lvfusion/lines/ScanPoints.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace lvf::lines
{
class ScanLineExtractor
{
   public:
	/** INI section [ScanLineExtractor]. The defaults suit the paper's SICK
	 * PLS (180 deg at 1 deg, 8 m, 5 cm range noise); the noise-bound
	 * thresholds (split distance, merge residual, radius of influence)
	 * follow each scan's own stated noise unless noiseFromScan is off. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		/** Set the noise-bound thresholds from each scan's range noise, the
		 * std its CObservation2DRangeScan::stdError states (MRPT's drivers
		 * fill it in, 1 cm by default; so do lvfusion's simulator and
		 * Middlebury importer), as withRangeNoise() does, instead of the
		 * fixed values below, which are then for scans that state none.
		 * Thresholds for 5 cm on a 1 cm scan fit a line through what is no
		 * line: on Middlebury Motorcycle (a ground-truth slice, 1 cm) one
		 * segment ran through the whole motorcycle (rays 9-75, RMS 6 cm),
		 * its wall up to 0.2 m in front of the returns, so criterion b hid
		 * the obstacles just before them (recall 0.217; from the scan's
		 * noise: 0.739). */
		bool noiseFromScan = true;
		/** Edges of the sphere-of-influence graph longer than this are cut
		 * whatever the radii: the graph always joins a point to its nearest
		 * neighbour, however far [m]. 0.5 m keeps a wall seen at 70 deg
		 * incidence at 8 m (0.41 m between rays) in one piece. */
		double maxGap = 0.5;
		/** A point's radius of influence is the distance to its nearest
		 * neighbour, but never less than this [m]: a return is only known to
		 * within the range noise, and with 5 cm of noise and 1 deg between
		 * rays the nearest neighbour is often nearer than the next point's
		 * depth jitter, which would cut straight walls into many clusters.
		 * About 2x the range noise: two points of one surface are then
		 * joined unless their ranges differ by > 4 std, while a box 0.3 m
		 * in front of a wall still stands apart from it. */
		double minInfluenceRadius = 0.10;
		/** Points (in scan order) on each side searched for the nearest
		 * neighbour and for edges [points]. */
		int influenceWindow = 3;
		/** IEPF splits a piece at its point farthest from the chord when
		 * that point is farther than this [m]. About 3x the range noise: the
		 * largest of ~50 Gaussian deviations is ~2.5 std, so a straight wall
		 * is rarely split by noise (and the merge pass repairs it when it
		 * is), while a corner or a box 15 cm proud of a wall is. */
		double splitDistance = 0.15;
		/** Adjacent pieces are merged when the line through their union has
		 * an RMS residual below this [m]: ~1.5x the range noise, the RMS of
		 * a straight surface being at most the noise. */
		double mergeResidual = 0.075;
		/** ... and when their directions differ by less than this [deg], or
		 * by no more than the noise explains (one line fits both no worse
		 * than two, chi-square at 99.9%): a 0.2 m piece of a face seen
		 * with 5 cm of noise has no direction to compare. */
		double mergeAngleDeg = 15;
		/** Pieces from different clusters merge only when the last point of
		 * one and the first of the next are closer than this, or than 3x the
		 * spacing of the points there plus 4 std of the noise of two points
		 * if more, and never farther than maxGap [m]: bridges a few missing
		 * returns on one wall (3 rays at 4 m: 0.28 m) and the gaps that
		 * noise opens between sparse returns at grazing incidence, not a
		 * doorway (0.6 m and more). */
		double mergeGap = 0.3;
		/** Segments with fewer points are dropped [points]. A cluster or an
		 * IEPF piece with fewer is no line of its own: its points may only
		 * join a neighbouring line (within splitDistance of it, and no
		 * farther from its end than pieces may be to merge, see mergeGap),
		 * or are dropped. */
		int minPoints = 5;
		/** Segments shorter than this are dropped [m]. */
		double minLength = 0.15;

		/** These options with the noise-bound thresholds set for a sensor
		 * of the given range noise std [m]: split distance 3x, merge
		 * residual 1.5x, minimum radius of influence 2x (the ratios of the
		 * defaults to the paper's 5 cm); never below 1 cm, 0.5 cm, 1 cm
		 * (real logs store ranges to 1 cm or 1 mm). */
		TOptions withRangeNoise(double rangeStd) const;
		/** The defaults, withRangeNoise(rangeStd). */
		static TOptions forRangeNoise(double rangeStd) { return TOptions().withRangeNoise(rangeStd); }

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;
	};

	/** A run of consecutive points (indices into ScanPoints), inclusive. */
	struct Cluster
	{
		size_t first = 0, last = 0;
		size_t size() const { return last - first + 1; }
	};

	/** Default options. (What `= TOptions()` would say, but GCC does not
	 * allow a nested struct's member initialisers to be used before the
	 * enclosing class is complete.) */
	ScanLineExtractor();
	explicit ScanLineExtractor(const TOptions& options);

	/** Segments of the scan's valid returns, robot frame, in scan order;
	 * with noiseFromScan, at the thresholds for the scan's stated noise. */
	std::vector<LineSegment> extract(
		const mrpt::obs::CObservation2DRangeScan& scan) const;
	std::vector<LineSegment> extract(const ScanPoints& points) const;

	/** Step 1 alone: every cluster, in scan order, small ones included. */
	std::vector<Cluster> clusters(const ScanPoints& points) const;

	const TOptions& options() const { return m_options; }

   private:
	TOptions m_options;
};

}  // namespace lvf::lines
