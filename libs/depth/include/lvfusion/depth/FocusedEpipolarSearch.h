#pragma once
// Stage 4 (paper §5, §6.1): depth from vision, only where the laser's model
// was found wrong, and only along the stretch of the epipolar line that can
// hold an obstacle the robot cares about (DisparityInterval.h).
//
// For each inconsistent or unmodelled pixel (on a grid of `pixel_stride`; an
// unmodelled one has no model depth, so only criterion c and the band bound
// it), every integer disparity in the allowed set is scored by NCC between
// the left window and the right window on the same row. The best score is
// accepted only if it is high, a true local maximum (its neighbours, even
// outside the allowed set, score lower: a peak cut by a bound is the model
// surface or something out of range, not an obstacle), holds on a smaller
// core window (not a window beside an object's silhouette), unique (no other
// peak of the whole line within `uniqueness_margin` of it, and the model's
// own disparity scoring clearly less: evaluation can flag a pixel for
// reasons other than an obstacle, e.g. fine texture, and then the model may
// still be the best explanation), and found again from the right image
// (left-right check). With `coarse_to_fine` the stretch and the line are
// scored on the half-resolution pair and the match refined at full
// resolution (CoarseToFineMatch.cpp). A parabola through the peak gives
// sub-pixel disparity; triangulation gives a robot-frame point, kept if it
// lies in the robot's height band.

#include <lvfusion/common/HeightBand.h>
#include <lvfusion/depth/DisparityInterval.h>
#include <lvfusion/depth/EpipolarScores.h>
#include <lvfusion/depth/MatchingLevel.h>
#include <lvfusion/evaluation/ModelEvaluator.h>
#include <mrpt/config/CLoadableOptions.h>

#include <Eigen/Core>
#include <vector>

namespace lvf::depth
{
struct VisualPoint
{
	float u = 0, v = 0;	 //!< rectified left pixel
	float disparity = 0;  //!< sub-pixel [px]
	float ncc = 0;	//!< score of the match
	Eigen::Vector3d robot;	//!< triangulated point, robot frame [m]
};

/** What the search made of one pixel of its grid (Result::outcome). */
enum class SearchOutcome : uint8_t
{
	NotSearched = 0,  //!< off the grid, consistent with the model, or not judged
	Untextured,	 //!< inconsistent, but too little texture to match
	EmptyRange,	 //!< the criteria leave no disparity to search
	Weak,  //!< the best score is below accept_ncc
	NotPeak,  //!< the best score sits on a bound, not on a peak
	Ambiguous,	//!< another peak, the model or the rest of the line scores as well
	LeftRight,	//!< the match does not find its way back
	OutOfBand,	//!< triangulated outside the robot's height band
	CoreMismatch,  //!< the core window does not match there, or the model explains it (or a side of it) as well
	BehindNearer,  //!< nearest first: what the criteria allow lies behind what earlier passes found on its bearing
	Accepted  //!< a visual point
};

struct DepthSearchStats
{
	size_t searchedPixels = 0;	//!< inconsistent pixels on the stride grid with a non-empty range
	size_t skippedUntextured = 0;	//!< inconsistent pixels with too little texture to match
	size_t skippedEmptyRange = 0;  //!< inconsistent pixels the criteria left nothing to search
	size_t skippedBehindNearer = 0;	 //!< nearest first: pixels whose whole range lies behind what earlier passes found
	size_t disparitiesTested = 0;  //!< NCC scores along the searched stretches (both levels when coarse-to-fine; not the left-right check's or the shifted windows')
	size_t accepted = 0;  //!< matches kept (in the band)
	size_t rejectedWeak = 0, rejectedNotPeak = 0, rejectedAmbiguous = 0, rejectedOutOfBand = 0;
	size_t rejectedLeftRight = 0;  //!< failed the left-right check
	size_t rejectedCore = 0;	//!< failed on the core window

	DepthSearchStats& operator+=(const DepthSearchStats& o)
	{
		searchedPixels += o.searchedPixels, skippedUntextured += o.skippedUntextured;
		skippedEmptyRange += o.skippedEmptyRange, skippedBehindNearer += o.skippedBehindNearer;
		disparitiesTested += o.disparitiesTested;
		accepted += o.accepted, rejectedWeak += o.rejectedWeak, rejectedNotPeak += o.rejectedNotPeak;
		rejectedAmbiguous += o.rejectedAmbiguous, rejectedOutOfBand += o.rejectedOutOfBand;
		rejectedLeftRight += o.rejectedLeftRight, rejectedCore += o.rejectedCore;
		return *this;
	}
	/** Counts one grid pixel's outcome (NotSearched: nothing). */
	void count(SearchOutcome o);
};

class FocusedEpipolarSearch
{
   public:
	/** INI section [FocusedEpipolarSearch]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		bool criterionA = true;	 //!< |Z - Zl| >= d_allow
		/** [m]; below the 0.15 m by which a hidden bearing's obstacle stands
		 * in front of the laser (DESIGN.md), or such obstacles could not be
		 * found: 0.25 cost Middlebury's Recycle 0.19 -> 0.47 recall. */
		double dAllow = 0.12;
		/** [px]; 0: off. Where the model is the floor and the band bounds
		 * the search, criterion a's margin in front of the floor is at most
		 * this much disparity, and the band's lower edge (what counts as an
		 * obstacle) decides the rest: along a ray grazing the floor d_allow
		 * of depth is only a few centimetres of height, and it hides the
		 * lowest part of obstacles standing on the floor. 2 px (the model
		 * check's reach): Middlebury Recycle recall 0.585 -> 0.698, boxes
		 * 7 cm tall 0.13 -> 0.72, every simulated room the same figures.
		 * It was off at first: in the closed loop it also finds thin table
		 * legs the laser misses, which turned overhang room 37 onto another
		 * route and into a floating box vision does not see there. With
		 * narrow gaps closed (ScanFusion's bridge_width) all 400 overhang
		 * rooms ran without a collision with it (Recycle then 0.717 ->
		 * 0.868; share/doc/lvfusion/measurements.md), so it is on. */
		double floorDisparityMargin = 2;
		bool criterionB = true;	 //!< Z <= Zl
		bool criterionC = true;	 //!< Zmin <= Z <= Zmax
		double zMin = 0.3, zMax = 5.0;	//!< [m]
		bool boundByBand = true;  //!< only depths whose height is in the robot band
		int pixelStride = 3;  //!< the step of the grid of pixels searched (those inconsistent or unmodelled), rows and columns
		/** Search the grid's rows coarse rows first: every 2^L-th grid
		 * row, then the rows halfway between, and so on down to every grid
		 * row, where a pass after the first searches a pixel only in front
		 * of the nearestFirstPoints-th nearest point the passes before it
		 * found on the pixel's bearing (NearestPerBearing.h; bearings with
		 * fewer points are searched in full). The fused scan keeps only a
		 * bearing's nearest obstacle, and an obstacle that fills many rows
		 * was matched and verified on every one of them. Two levels, 3
		 * points: the search's instructions -26 % on the box room, the
		 * same recall and phantom rate (README, measurements.md). 0: off,
		 * every grid row in one pass. */
		int nearestFirstLevels = 2;
		int nearestFirstPoints = 3;
		double acceptNcc = 0.8;	 //!< a match must score at least this
		double uniquenessMargin = 0.1;	//!< other peaks must score this much less
		/** Left window std needed to search, in multiples of the image's
		 * noise (the evaluation's estimate, ImageNoise.h), and at least
		 * minTextureStd [grey levels]. 2.25 x 2.22 = 5.0 on the simulator,
		 * the absolute gate measured there before (8 -> 5: seeded rooms 1-6
		 * recall 0.820 -> 0.838, phantom rate 0.033 both; box room 0.908 ->
		 * 0.924; 4 and 3 added a phantom and found nothing more). Relative
		 * to the noise, the clean Middlebury images are searched down to
		 * ~1 grey level: Recycle recall 0.434 -> 0.604, no phantom. */
		double textureNoiseRatio = 2.25;
		double minTextureStd = 1.0;
		/** The left window std a pixel needs to be searched, for an image
		 * of this noise [grey levels]. */
		double textureGate(double noiseStd) const
		{
			return lvf::evaluation::noiseRelativeGate(noiseStd, textureNoiseRatio, minTextureStd);
		}
		int peakContext = 8;  //!< NCC also scored this far outside the allowed set [px]
		bool verifyFullLine = true;	 //!< accepted matches must beat the whole line
		/** The right window of a match, matched back along the left row over
		 * the same disparities, must find the left pixel again (+-1 px). */
		bool leftRightCheck = true;
		/** A match must also hold on this smaller window centred on the
		 * pixel, and not better at the model's disparity [px, odd;
		 * 0: off]: a window centred just outside an object's silhouette
		 * still holds the object and matches at its depth, so objects would
		 * come out up to half a window too wide. */
		int coreWindow = 5;
		double coreAcceptNcc = 0.5;	 //!< the core window's NCC at the match
		/** The match must not be explained better by the model on a window
		 * of the same size shifted sideways until the pixel lies on its
		 * edge (at least accept_ncc there, and better than either shifted
		 * window at the match): the core window is smaller, but still
		 * reaches onto an object a few pixels away. Phantom bearings, rooms
		 * 1-6 / 11-16 / 21-26 / 31-36 / held-out 41-46 / 51-56: 19 / 17 /
		 * 12 / 25 / 12 / 28 -> 15 / 15 / 9 / 19 / 8 / 20, recall bearings
		 * +1 / 0 / -1 / -2 / -3 / -3 (an obstacle's outermost bearing).
		 * On by default since 2026-12-03, with the sub-pixel steps below:
		 * the closed loop, whose routes it changes, now keeps off what the
		 * plan assumes of an overhang (NavigationLoopOptions::
		 * navigatorKeepsOffAssumed), and went without collision with them
		 * (share/doc/lvfusion/measurements.md). */
		bool shiftedWindows = true;
		/** Find the match, and verify that it is unique and finds its way
		 * back, on the half-resolution pair (windows of half the side, half
		 * the columns: ~8x fewer products), then refine it on the full
		 * pair, where the local tests and the sub-pixel peak are taken. */
		bool coarseToFine = true;
		/** Lucas-Kanade steps along the row after the parabola's sub-pixel
		 * peak, on the window weighted by a Gaussian of `subpixelSigma` px
		 * round its centre (SubpixelRefinement.h; 0: the parabola alone). A
		 * window over two surfaces puts the parabola between their
		 * disparities; the weights let the centre pixel's surface decide.
		 * At 2 steps: recalled / phantom bearings, seeded rooms 1-6, 11-16,
		 * 21-26, 31-36 together, 997 / 73 -> 1009 / 61 (rooms 1-6: recall
		 * 0.863 -> 0.877, phantom rate 0.033 -> 0.024). On by default with
		 * the shifted windows (above). */
		int subpixelIterations = 2;
		double subpixelSigma = 3.0;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;
	};

	struct Result
	{
		std::vector<VisualPoint> points;
		DepthSearchStats stats;
		/** SearchOutcome per left pixel, to see why nothing was found. */
		cv::Mat1b outcome;
		/** The outermost columns points can lie at: the first and last grid
		 * columns' matches are extended to the image columns their windows
		 * cover beyond them, where no window fits. */
		float firstColumn = 0, lastColumn = 0;
	};

	FocusedEpipolarSearch() = default;
	explicit FocusedEpipolarSearch(const TOptions& options) : m_options(options) {}

	/** On OpenCV's threads (cv::setNumThreads; the same result on any
	 *  number, bit for bit, in the same order).
	 *  @param windowSize the NCC window, the one the evaluation used (its
	 *  left-image window statistics are reused).
	 *  @param floorHeight the model's floor, z in the robot frame [m]. */
	Result search(
		const cv::Mat1b& left, const cv::Mat1b& right,
		const lvf::evaluation::ModelEvaluation& evaluation, int windowSize,
		const lvf::evaluation::RectifiedGeometry& geometry, const HeightBand& band,
		double floorHeight) const;

	const TOptions& options() const { return m_options; }

   private:
	struct Frame;
	struct Pass;
	struct RowsFound;
	/** Searches the pass's rows below endRow, in bands on OpenCV's threads;
	 * the points in row order. */
	RowsFound searchPass(
		const Pass& pass, int endRow, MatchingLevel& full, MatchingLevel* coarse, const Frame& frame,
		cv::Mat1b& outcome) const;
	/** Searches the pass's rows in [firstRow, endRow) with these levels
	 * (their scores are this call's alone), adding to `found` and marking
	 * `outcome`. */
	void searchRows(
		int firstRow, int endRow, const Pass& pass, MatchingLevel& full, MatchingLevel* coarse,
		const Frame& frame, RowsFound& found, cv::Mat1b& outcome) const;
	/** One grid pixel left to the search: the outcome, and with Accepted
	 * its point (and the image-edge columns' beside it) added to `points`. */
	SearchOutcome searchPixel(int u, int v, const Pass& pass, MatchingLevel& full, MatchingLevel* coarse,
		const Frame& frame, std::vector<VisualPoint>& points) const;
	/** Criteria a, b, c and the band for the left pixel in column u whose
	 * ray (robot frame) leaves the camera centre `camera`; `floorModel`:
	 * the model's surface there is the floor (floorDisparityMargin). */
	DisparitySet allowedDisparities(
		int u, double modelDisparity, const Eigen::Vector3d& ray, const Eigen::Vector3d& camera,
		int half, const lvf::evaluation::RectifiedGeometry& g, const HeightBand& band,
		bool floorModel) const;
	/** One left pixel to match: where, what the model says, what may be searched. */
	struct PixelQuery
	{
		int u, v;
		float leftMean, leftStd;  //!< its window, as the evaluation saw it
		double modelDisparity;	//!< [px], 0: no model surface
		const DisparitySet& set;
		const lvf::evaluation::RectifiedGeometry& g;
		/** Full-resolution right column of disparity d. */
		double column(double d) const { return u + g.cxOffset - d; }
	};
	/** The outcome for one pixel; when Accepted, the full-resolution column
	 * of the match, its score and its neighbours' (for the sub-pixel peak). */
	struct Match
	{
		SearchOutcome outcome = SearchOutcome::NotSearched;
		int x = -1;
		float score = -2, before = -2, after = -2;
	};
	Match matchAtFullResolution(MatchingLevel& full, const PixelQuery& q) const;
	Match matchCoarseToFine(MatchingLevel& full, MatchingLevel& coarse, const PixelQuery& q) const;
	/** The shifted-window test (TOptions::shiftedWindows) for the match at
	 * full-resolution right column matchX: the model explains one side of
	 * the pixel, and better than the match explains either. */
	bool modelExplainsASide(MatchingLevel& full, const PixelQuery& q, int matchX) const;
	/** The tests taken at full resolution around the best column: strong
	 * enough, a true peak, the core window agrees, the model explains the
	 * pixel clearly worse. Fills `m` and returns whether all pass. */
	bool passesLocalTests(MatchingLevel& full, const PixelQuery& q, int bestX, float best, Match& m) const;
	/** No other peak of the line within [xNear, xFar] scores within the
	 * uniqueness margin of `best` at `bestX`. */
	bool beatsTheRestOfTheLine(EpipolarScores& scores, int bestX, float best, int xNear, int xFar) const;
	/** Left-right check: the right window at column x, scored against the
	 * left windows of row v over the disparities of right columns
	 * [xNear, xFar] as seen from u, scores best at u (+-1). */
	bool findsItsWayBack(MatchingLevel& level, int u, int v, int x, int xNear, int xFar) const;
	/** The accepted match `m` of pixel q, whose ray is `ray`, refined to
	 * sub-pixel disparity and triangulated: Accepted with its point added to
	 * `points` (and, at the grid's outermost columns, the image-edge
	 * columns' its window covers), or OutOfBand. */
	SearchOutcome triangulate(const PixelQuery& q, const Match& m, const Eigen::Vector3d& ray, MatchingLevel& full,
		const Frame& frame, std::vector<VisualPoint>& points) const;

	TOptions m_options;
};

}  // namespace lvf::depth
