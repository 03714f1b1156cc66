#pragma once
// The planar model seen from the rectified left camera: for every pixel, the
// disparity (f B / depth) of the nearest model surface its ray meets.
//
// Ray casting every pixel against every wall would cost O(pixels x walls).
// Instead each plane is rasterised: in a rectified camera the inverse depth
// of a plane is an affine function of (u, v), and the wedge of rays that meet
// a wall between its endpoints is bounded by two more affine functions (the
// vertical planes through the camera centre and each endpoint). Per image row
// each wall therefore covers one interval of columns, found in O(1), which is
// filled with a running maximum of disparity (nearest surface wins).

#include <lvfusion/evaluation/RectifiedStereo.h>
#include <lvfusion/model/PlanarSceneModel.h>

namespace lvf::evaluation
{
/** 0 where the ray meets no model surface (or only behind the camera). */
cv::Mat1f renderModelDisparity(
	const lvf::model::PlanarSceneModel& model, const RectifiedGeometry& geometry);

}  // namespace lvf::evaluation
