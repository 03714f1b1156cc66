#pragma once
// Is the stereo calibration believable? A scene may contradict the planar
// model over most of the image -- a cluttered room, overhangs hiding the
// laser's own returns from the camera, a real scene like Middlebury's -- while
// the calibration is perfect. But the floor in front of the robot is almost
// always visible and the model's floor is right wherever the camera sees
// floor. So the share of the model's floor pixels the evaluation found
// consistent tells a wrong calibration (a wrong baseline or a rotated camera
// contradicts the whole floor) from a busy scene (where objects cover only
// part of it); the share of all judged pixels that disagree covers frames
// without a judged floor. Measured in test_fusion_pipeline and on Middlebury
// (see CLaserStereoFusion::TOptions::minFloorAgreement).
//
// Both checks take a pixel as agreeing with the model at an NCC of their own
// (CLaserStereoFusion::TOptions::calibrationNcc), not at the evaluation's
// threshold: that one decides where to search, and a stricter one there
// (more pixels searched) must not make a busy scene's floor look wrong.

#include <lvfusion/evaluation/ModelEvaluator.h>

namespace lvf::fusion
{
/** What the calibration checks weigh, counted in one pass over the judged
 * (consistent or inconsistent) pixels. */
struct CalibrationEvidence
{
	size_t floorJudged = 0;	 //!< judged pixels where the model's nearest surface is the floor
	size_t floorAgreeing = 0;  //!< of those, with an NCC of at least the checks'
	size_t judged = 0;	//!< all judged pixels
	size_t disagreeing = 0;	 //!< of those, with an NCC below the checks'

	/** floorAgreeing / floorJudged; 1 when no floor pixel was judged. */
	double floorAgreement() const { return floorJudged ? double(floorAgreeing) / double(floorJudged) : 1.0; }
	/** disagreeing / judged; 0 when nothing was judged. */
	double disagreeingShare() const { return judged ? double(disagreeing) / double(judged) : 0.0; }
};

/** Counts over the pixels the evaluation judged (all of them, or the grid
 * of ModelEvaluator::evaluateGrid: ModelEvaluation::grid): the floor's
 * pixels are those whose model disparity is that of the floor at
 * `floorHeight` (robot frame); a pixel agrees at an NCC of `agreeingNcc` or
 * more. */
CalibrationEvidence calibrationEvidence(
	const lvf::evaluation::RectifiedGeometry& geometry, const lvf::evaluation::ModelEvaluation& evaluation,
	double floorHeight, double agreeingNcc);

}  // namespace lvf::fusion
