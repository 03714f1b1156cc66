#pragma once
// The perception figures of DESIGN.md ("Words and metrics used in issues"),
// computed per frame from a laser scan, a truth scan and the camera geometry.

#include <lvfusion/common/HeightBand.h>
#include <lvfusion/common/Medians.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include <vector>

namespace lvf::metrics
{
using lvf::HeightBand;

/** Per bearing: does the left camera see the obstacle column there? True when
 * some point of the band (sampled every 5 cm) at the truth range on that
 * bearing (or at `rangeIfNoTruth`) lies inside the left image, with the
 * stored distortion (every coefficient, k4-k6 included). Scan and cameras
 * are both relative to the robot. */
std::vector<bool> bearingsInView(
	const mrpt::obs::CObservation2DRangeScan& scan,
	const std::vector<float>& truth,
	const mrpt::obs::CObservationStereoImages& stereo, const HeightBand& band,
	double rangeIfNoTruth);

/** Hidden bearing: in view, and truth nearer than the laser by more than
 * `margin` (0.15 m) -- something the laser cannot see is in the way. An
 * invalid laser return counts as the laser's max range. */
std::vector<bool> hiddenBearings(
	const mrpt::obs::CObservation2DRangeScan& laser,
	const std::vector<float>& truth, const std::vector<bool>& inView,
	double margin = 0.15);

/** A bearing's obstacle is seen by both cameras when the seen truth scan
 * (StereoSeenTruth.h) has a point as near as the truth, within recall's
 * 0.10 m (the seen scan bins points by bearing). */
inline bool seenByBothCameras(float seenTruth, float truth) { return seenTruth <= truth + 0.10; }

}  // namespace lvf::metrics

namespace lvf::metrics
{
/** DESIGN.md's perception figures for one fused scan, over the in-view
 * bearings whose truth is within `maxRange` (Zmax). */
struct FusionScore
{
	size_t inView = 0, hidden = 0, recalled = 0, phantoms = 0, withTruth = 0;
	/** With a seen truth scan (StereoSeenTruth.h): the hidden bearings whose
	 * obstacle both cameras see, and of those the recalled. */
	size_t seenHidden = 0, seenRecalled = 0;
	double recall() const { return hidden ? double(recalled) / double(hidden) : 1.0; }
	double phantomRate() const { return inView ? double(phantoms) / double(inView) : 0.0; }
	double seenRecall() const { return seenHidden ? double(seenRecalled) / double(seenHidden) : 1.0; }
	/** Median |fused - truth| where truth exists [m] (0: none). Computed
	 * when asked, from every error added: a run's add() per frame stays
	 * cheap however long the run. */
	double rangeErrorMedian() const { return lvf::common::upperMedian(errors, 0.f); }
	/** The same over the hidden bearings only [m]. */
	double hiddenRangeErrorMedian() const { return lvf::common::upperMedian(hiddenErrors, 0.f); }
	/** Adds another frame's counts and errors. */
	void add(const FusionScore& other);
	std::vector<float> errors, hiddenErrors;
};

/** How one bearing counts in its scan's FusionScore. */
struct BearingVerdict
{
	/** Counted among the in-view bearings: in view, and the truth or the
	 * laser within Zmax, or else the fused scan nearer than the laser and
	 * Zmax (vision reporting something there). */
	bool scored = false;
	bool hidden = false;  //!< scored, hidden (DESIGN.md), and the truth within Zmax
	bool recalled = false;	//!< hidden, and the fused range at most truth + 0.10 m
	bool phantom = false;  //!< scored, and the fused range nearer than min(truth, laser) - 0.10 m
};

/** Each bearing's verdict, as scoreFusedScan counts it (so that a per-bearing
 * listing adds up to the figures). */
std::vector<BearingVerdict> judgeBearings(
	const mrpt::obs::CObservation2DRangeScan& laser,
	const mrpt::obs::CObservation2DRangeScan& fused, const std::vector<float>& truth,
	const std::vector<bool>& inView, double maxRange);

/** The figures of bearings judged by judgeBearings (with the same fused
 * scan, truth and Zmax): for a caller that also lists the verdicts. */
FusionScore scoreVerdicts(
	const std::vector<BearingVerdict>& verdicts, const mrpt::obs::CObservation2DRangeScan& fused,
	const std::vector<float>& truth, double maxRange, const std::vector<float>* seenTruth = nullptr);

/** `seenTruth`, if given: the truth scan of what both cameras see, for
 * seenHidden and seenRecalled. */
FusionScore scoreFusedScan(
	const mrpt::obs::CObservation2DRangeScan& laser,
	const mrpt::obs::CObservation2DRangeScan& fused, const std::vector<float>& truth,
	const std::vector<bool>& inView, double maxRange, const std::vector<float>* seenTruth = nullptr);
}  // namespace lvf::metrics
