#pragma once
// The global layer over the reactive navigator (paper Secs. 6-7: a path by
// value iteration, the reactive method steering locally along it). Reactive
// methods see only the target's direction and the obstacles around them, so
// behind a concave obstacle (a U of boxes, a table with a wall behind it)
// they stall in a local minimum. Every few sensing steps the loop plans on
// the robot's own obstacle grid (laser + vision cells; unobserved cells are
// free, so the plan is optimistic and is corrected as the robot sees more)
// with lvf::planning's value iteration, and hands the navigator as its
// target the farthest point of that path, within a look-ahead distance along
// it, that the robot can reach in a straight line on the grid (a subgoal
// round a corner would pull a reactive method into the corner).
//
// Unobserved cells are free, except round what only vision found: there the
// plan assumes the overhang goes on into what the cameras have not seen
// (GuidanceOptions::overhangDepth).
//
// No path on the grid means every way to the target is closed by obstacles
// the robot has seen: the target is unreachable as far as it can know.

#include <lvfusion/navigation/LocalObstacleGrid.h>
#include <lvfusion/planning/ValueIterationPlanner.h>

#include <string>
#include <vector>

namespace lvf::navigation
{
struct GuidanceOptions
{
	double robotRadius = 0.30;	//!< obstacles are grown by this [m]
	/** Extra growth so the path keeps off obstacles [m]; a plan that fails
	 * with it is retried with half of it, then without. */
	double clearance = 0.20;
	/** The cameras see an overhang (a floating box, a table top) from the
	 * front: its sides and back, which the laser passes under, are cells
	 * vision never looked at. The plan keeps off such cells within this
	 * distance of a cell only vision found occupied, as if the object went
	 * on that far (the random rooms' floating boxes are up to 0.7 m,
	 * table tops 0.6-0.8 m deep). Where that closes every way at the full
	 * clearance, the plan tries half the clearance, and only then drops the
	 * assumption (the clearance's own fall-backs following, down to the bare
	 * radius): measured, a robot squeezed through gaps between assumed parts
	 * with the bare radius dithered until its timeout
	 * (share/doc/lvfusion/measurements.md) [m]; 0: off. */
	double overhangDepth = 0.6;
	/** The cells between `unseenFrom` and this far from the robot whose
	 * band column the cameras have not seen free (at least
	 * `unseenMinHeight` of it: LocalObstacleGrid::assumeUnseenNear) are
	 * avoided with the overhangs' assumed depth [m]; 0: off. Nearer cells
	 * are left alone: the cameras, looking down from 1 m, never see the
	 * whole band there, and the plan's growth would wall the robot in. */
	double unseenRadius = 0;
	double unseenFrom = 0.6;  //!< [m]
	double unseenMinHeight = 0.15;	//!< [m]
	double lookahead = 1.5;	 //!< the subgoal is at most this far along the path [m]
	/** A blocked start (the robot brushing an obstacle cell) or goal is
	 * moved to the nearest traversable cell within this distance [m]. */
	double snapRadius = 0.5;
	double occupiedBelow = 0.45;  //!< as NavigationLoopOptions::occupiedBelow
};

struct Guidance
{
	enum class Status
	{
		Path,  //!< `subgoal` is on a path to the target
		Unreachable,  //!< no path on the robot's grid joins it to the target
		Direct	//!< no plan possible here (e.g. boxed in by its own cells): steer at the target
	};
	Status status = Status::Direct;
	mrpt::math::TPoint2D subgoal;
	bool subgoalIsTarget = true;  //!< the path's remainder is shorter than the look-ahead
	std::vector<mrpt::math::TPoint2D> path;	 //!< from the (snapped) robot position to the target
	double pathLength = 0;	//!< [m]
	/** The path keeps off the assumed cells (overhang depth, unseen
	 * columns); false: they closed every way and were dropped. */
	bool keepsOffAssumed = false;
	/** The clearance the path keeps (GuidanceOptions::clearance, or less
	 * where that closed every way) [m]. */
	double clearance = 0;
	std::string detail;	 //!< why, for Unreachable / Direct
};

/** One plan from `robot` to `target` on `grid`. */
Guidance planGuidance(
	const LocalObstacleGrid& grid, const mrpt::math::TPoint2D& robot,
	const mrpt::math::TPoint2D& target, const GuidanceOptions& options);

}  // namespace lvf::navigation
