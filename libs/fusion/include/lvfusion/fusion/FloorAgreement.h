#pragma once
// Is the stereo calibration believable? A scene may contradict the planar
// model over most of the image -- a cluttered room, overhangs hiding the
// laser's own returns from the camera, a real scene like Middlebury's -- while
// the calibration is perfect. But the floor in front of the robot is almost
// always visible and the model's floor is right wherever the camera sees
// floor. So the share of the model's floor pixels the evaluation found
// consistent tells a wrong calibration (a wrong baseline or a rotated camera
// contradicts the whole floor) from a busy scene (where objects cover only
// part of it). Measured in test_fusion_pipeline and on Middlebury (see
// CLaserStereoFusion::TOptions::minFloorAgreement).
//
// Both checks take a pixel as agreeing with the model at an NCC of their own
// (CLaserStereoFusion::TOptions::calibrationNcc), not at the evaluation's
// threshold: that one decides where to search, and a stricter one there
// (more pixels searched) must not make a busy scene's floor look wrong.

#include <lvfusion/evaluation/ModelEvaluator.h>

namespace lvf::fusion
{
struct FloorAgreement
{
	size_t judged = 0;	//!< sampled model-floor pixels judged (consistent or not)
	size_t consistent = 0;	//!< of those, agreeing with the model (NCC at least the check's)

	/** consistent / judged; 1 when nothing could be judged. */
	double fraction() const { return judged ? double(consistent) / double(judged) : 1.0; }
};

/** Of the judged pixels (every `stride`-th row and column) where the
 * model's nearest surface is the floor at `floorHeight` (robot frame) --
 * those whose model disparity is the floor's own --, how many have an NCC of
 * at least `agreeingNcc`. */
FloorAgreement floorAgreement(
	const lvf::evaluation::RectifiedGeometry& geometry, const lvf::evaluation::ModelEvaluation& evaluation,
	double floorHeight, double agreeingNcc, int stride = 4);

/** The share of all judged pixels whose NCC is below `agreeingNcc` (0 when
 * none was judged). */
double disagreeingShare(const lvf::evaluation::ModelEvaluation& evaluation, double agreeingNcc);

}  // namespace lvf::fusion
