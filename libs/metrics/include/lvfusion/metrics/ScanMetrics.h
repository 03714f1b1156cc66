#pragma once
// The perception figures of DESIGN.md ("Words and metrics used in issues"),
// computed per frame from a laser scan, a truth scan and the camera geometry.

#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationStereoImages.h>

#include <vector>

namespace lvf::metrics
{
struct HeightBand
{
	double low = 0.05;	//!< obstacle_min_height [m]
	double high = 1.20;	 //!< robot_height [m]
};

/** Per bearing: does the left camera see the obstacle column there? True when
 * some point of the band (sampled every 5 cm) at the truth range on that
 * bearing (or at `rangeIfNoTruth`) projects inside the left image, with the
 * stored distortion. Scan and cameras are both relative to the robot. */
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

}  // namespace lvf::metrics
