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

#include <lvfusion/evaluation/ModelEvaluator.h>

namespace lvf::fusion
{
struct FloorAgreement
{
	size_t judged = 0;	//!< sampled model-floor pixels judged (consistent or not)
	size_t consistent = 0;	//!< of those, found consistent with the model

	/** consistent / judged; 1 when nothing could be judged. */
	double fraction() const { return judged ? double(consistent) / double(judged) : 1.0; }
};

/** Counts the evaluation's verdicts on the pixels (every `stride`-th row and
 * column) where the model's nearest surface is the floor at `floorHeight`
 * (robot frame): those whose model disparity is the floor's own. */
FloorAgreement floorAgreement(
	const lvf::evaluation::RectifiedGeometry& geometry, const lvf::evaluation::ModelEvaluation& evaluation,
	double floorHeight, int stride = 4);

}  // namespace lvf::fusion
