#pragma once
// A fused frame's rays into the SeenSpace: what the cameras looked through.

#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/navigation/SeenSpace.h>
#include <mrpt/poses/CPose2D.h>

namespace lvf::navigation
{
/** Carves `space` with the rays of the frame's evaluated pixels whose depth
 * is known: the model's surface where the evaluation found it consistent,
 * the visual point where the search matched one. An untextured pixel is not
 * known: a box face seen close up is blurred below the texture gate
 * (overhang room 50: carving through such pixels took the robot into the
 * box). `robot`: the pose the frame was taken at. */
void carveSeenRays(
	const lvf::fusion::CLaserStereoFusion::Result& frame, const mrpt::poses::CPose2D& robot, SeenSpace& space);

}  // namespace lvf::navigation
