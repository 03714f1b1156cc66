#pragma once
// Which vertical walls the laser's model stands on (paper §3 raises one per
// line segment). Returns that fit no segment -- a table leg, the short side
// of a box seen at a slant, a few rays through a gap -- are things the laser
// did see; left out, the model has nothing there, the cameras see the object
// where the model says "wall behind" or "nothing", and stage 4 spends its
// time finding again what the laser already knew. So each such return also
// gets a narrow facet: square to its ray, as wide as the angle between rays
// at its range, so that neighbouring stray returns join into a staircase.

#include <lvfusion/lines/LineSegment.h>
#include <lvfusion/model/PlanarSceneModel.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <vector>

namespace lvf::fusion
{
/** One wall per segment, then (if `facetStrayReturns`) one facet per valid
 * return outside every segment's ray range; robot frame. */
std::vector<lvf::model::VerticalWall> modelWalls(
	const mrpt::obs::CObservation2DRangeScan& scan, const std::vector<lvf::lines::LineSegment>& segments,
	bool facetStrayReturns);

}  // namespace lvf::fusion
