#pragma once
// How a closed-loop run ended, and what it measured.

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <limits>
#include <string>
#include <vector>

namespace lvf::navigation
{
enum class Outcome
{
	Reached,  //!< within the target tolerance, no collision
	Collision,	//!< the robot's body touched a solid of the world
	Timeout,  //!< neither reached nor collided in the allotted time
	NavigatorError,	 //!< the navigator gave up (e.g. target blocked)
	Unreachable,  //!< no path to the target on the robot's grid (global guidance)
	// Scenarios that cannot be run at all (checked before the first step):
	StartInCollision,
	TargetInObstacle,
	InvalidPose,  //!< a NaN/inf start, target, or robot pose during the run
};

/** "reached", "collision", ... (as in metrics lines and CSV). */
const char* outcomeName(Outcome o);
/** The program's exit status for a single run (documented in --help):
 * 0 reached, 3 ran but did not reach, 4 scenario could not be run. */
int outcomeExitStatus(Outcome o);

struct NavigationMetrics
{
	Outcome outcome = Outcome::Timeout;
	std::string detail;	 //!< one line: why it ended
	int collisions = 0;	 //!< 0 or 1: the run stops at the first
	double time = 0;  //!< simulated time [s]
	double pathLength = 0;	//!< [m], of a reached run up to the tolerance circle (see below)
	double finalDistance = std::numeric_limits<double>::quiet_NaN();	//!< to target [m]
	double minClearance = std::numeric_limits<double>::infinity();	//!< [m], <0: collided
	std::string minClearanceBox;  //!< the solid it was measured against
	double meanCycleMs = 0;	 //!< wall time per control cycle incl. sensing
	size_t cycles = 0, sensingUpdates = 0;
	size_t plans = 0;  //!< global-guidance plans made
	std::vector<mrpt::math::TPose2D> trajectory;  //!< true poses, one per cycle

	bool reached() const { return outcome == Outcome::Reached; }
	/** One line: outcome, collisions, time, path length, clearance, cycle time. */
	std::string summary() const;
};

/** How far the straight step `from` -> `to` runs on after first entering the
 * circle (`centre`, `radius`): 0 if it never enters it, |to - from| if it
 * starts inside. A reached run's path ends where it enters the target
 * tolerance, not at the end of its last control step: otherwise a faster
 * robot's longer last step, ending deeper inside, counts as a longer path
 * (measured: 0.5 cm of the 2.4 cm between VFH and ND in the laser-visible
 * rooms). */
double stepLengthInsideCircle(
	const mrpt::math::TPoint2D& from, const mrpt::math::TPoint2D& to,
	const mrpt::math::TPoint2D& centre, double radius);

}  // namespace lvf::navigation
