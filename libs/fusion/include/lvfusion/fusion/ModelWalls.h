#pragma once
// Which vertical walls the laser's model stands on (paper §3 raises one per
// line segment). Returns that fit no segment -- a table leg, the short side
// of a box seen at a slant, a few rays through a gap -- are things the laser
// did see; left out, the model has nothing there, the cameras see the object
// where the model says "wall behind" or "nothing", and stage 4 spends its
// time finding again what the laser already knew. So each such return also
// gets a narrow facet: square to its ray, as wide as the angle between rays
// at its range, so that neighbouring stray returns join into a staircase.
//
// Two segments on neighbouring rays whose ends nearly meet are one surface
// the laser followed round a corner (or a kink the line fit split): each
// ends at its own last point projected onto its line, so a few centimetres
// open between them, and through that slit the cameras' rays reach the
// model's floor metres behind. Measured (lvf-navigate, overhang room 1, a
// room's corner 1.3 m ahead): a 10 cm slit, 3.4 deg wide from the cameras,
// made the model's only "floor" pixels there, all contradicted by the wall
// the images show, and the frame fell back to the laser as if its stereo
// calibration were wrong. So such ends are joined by a wall as well.

#include <lvfusion/lines/LineSegment.h>
#include <lvfusion/model/PlanarSceneModel.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace lvf::fusion
{
/** One wall per segment; one joining the ends of two segments whose rays
 * are neighbours (at most one ray between) if the ends lie within
 * `joinGap` of each other (0: none); then (if `facetStrayReturns`) one
 * facet per valid return outside every segment's ray range; robot frame. */
std::vector<lvf::model::VerticalWall> modelWalls(
	const mrpt::obs::CObservation2DRangeScan& scan, const std::vector<lvf::lines::LineSegment>& segments,
	bool facetStrayReturns, double joinGap = 0);

}  // namespace lvf::fusion
