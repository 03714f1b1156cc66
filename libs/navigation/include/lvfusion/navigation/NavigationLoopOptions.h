#pragma once
// The closed loop's own settings: section [NavigationLoop] of the navigation
// INI (the other sections are MRPT's reactive navigator's; see
// share/lvfusion/config/navigate.ini).

#include <mrpt/config/CLoadableOptions.h>

namespace lvf::navigation
{
struct NavigationLoopOptions : public mrpt::config::CLoadableOptions
{
	double controlPeriod = 0.1;	 //!< one navigation step and robot motion [s]
	int sensingEvery = 2;  //!< a sensing + grid update every this many steps
	double timeout = 120;  //!< simulated time before giving up [s]
	double targetTolerance = 0.30;	//!< reached when this close [m]
	double gridResolution = 0.05;  //!< local occupancy grid cell [m]
	double obstacleRange = 4.0;	 //!< grid cells this near go to the navigator [m]
	/** A grid cell is an obstacle when its free probability is below this
	 * (one laser hit takes a fresh cell to 0.35 with MRPT's defaults). */
	double occupiedBelow = 0.45;
	/** The navigator also senses the cells this near an obstacle only
	 * vision found (LocalObstacleGrid): vision's edges are a bin and a few
	 * centimetres uncertain, and a floating box's sides it never saw go on
	 * past them [m]; 0: off, the default. Measured (overhang rooms, fused
	 * VFH): 0.05 m took the shifted windows + sub-pixel perception from 3
	 * collisions in rooms 1-100 to none (100 reached), but over rooms
	 * 1-300 it collided in 2 (151, 286), and with the shipped perception
	 * in 2 of rooms 1-100 where the shipped loop has none: another change of
	 * routes, not a fix (share/doc/lvfusion/measurements.md). */
	double visionObstacleMargin = 0;
	/** Give the fusion the robot's pose, so that its memory of earlier
	 * frames' points ([VisualPointMemory], on in fusion.ini) works in the
	 * loop; off, the default: the loop's local grid already remembers what
	 * the cameras saw. Measured (overhang rooms 1-100, fused VFH): 99
	 * reached and 1 collision (room 66, a floating box's unseen side on
	 * another route) against 97 and none without
	 * (share/doc/lvfusion/measurements.md). */
	bool fusionPointMemory = false;

	// Global guidance (GlobalGuidance.h): a value-iteration path on the
	// robot's grid, the navigator steering at a point of it ahead.
	bool globalGuidance = true;	 //!< off: the navigator steers at the target itself
	double guidancePeriod = 1.0;  //!< replan this often [s] (and when the subgoal is reached)
	double guidanceLookahead = 1.5;	 //!< the navigator's subgoal is this far along the path [m]
	double guidanceClearance = 0.20;  //!< the path keeps this much more than the robot's radius off obstacles [m]
	/** Cameras see an overhang's near faces only; the plan assumes it goes
	 * on this far into what vision never looked at (GuidanceOptions) [m]. */
	double guidanceOverhangDepth = 0.6;
	/** While the plan keeps its full clearance off the overhangs' assumed
	 * far parts, the navigator senses them too
	 * (LocalObstacleGrid::senseAssumedOverhangs): a reactive method
	 * steering at a point of the path ahead cuts the path's corners, and
	 * round a floating box whose side the cameras never saw that corner is
	 * the box. Not along a path the plan had to lay through them, nor
	 * round the robot itself, nor where only a narrower way is left (VFH+
	 * would find no valley). Off by default: measured with the shifted
	 * windows and the sub-pixel steps (overhang rooms 1-200) it kept the
	 * robot off the boxes it had hit in 3 rooms, but one more still
	 * collided and 10 timed out (share/doc/lvfusion/measurements.md). */
	bool navigatorKeepsOffAssumed = false;
	/** Fused runs: the overhangs' assumed far parts also take the cells
	 * vision's 2D grid calls free but whose band column the cameras have
	 * not seen through (SeenSpace.h, unseenMinHeight): a bearing where
	 * vision found nothing clears its cells up to the laser's range, under
	 * a floating box's unmatched side as well. Off by default (with
	 * navigatorKeepsOffAssumed: more assumed cells, more rooms where the
	 * robot stalls among them). */
	bool guidanceOverhangUnseen = false;
	/** The plan also keeps off the cells from guidanceUnseenFrom to this far
	 * from the robot whose band column the cameras have not seen free
	 * (SeenSpace.h; dropped with the overhang depth if that closes every
	 * way, and then the robot first turns to look at the first such cell
	 * on its path) [m]; 0: off, the default. Fused runs only. Measured
	 * (overhang rooms 1-100, fused VFH, both search options, 1.5 m): the
	 * rooms those collided in reached, but 2 others collided, round a box
	 * no pixel matched on a plan that had given the unseen cells up
	 * (share/doc/lvfusion/measurements.md). */
	double guidanceUnseenRadius = 0;
	double guidanceUnseenFrom = 0.6;  //!< [m]
	/** A column is unseen when at least this much of its band has not
	 * been seen free (less: gaps between the pixels' rays) [m]. */
	double unseenMinHeight = 0.15;
	/** With guidanceUnseenRadius or guidanceOverhangUnseen: the disk round the start taken as seen
	 * free, where the cameras (looking down from 1 m) cannot see the whole
	 * band [m]. */
	double startSeenRadius = 1.15;
	/** The run ends as "unreachable" when no path exists on the grid for
	 * this long (a few replans: one bad view does not end a run) [s]. */
	double unreachableAfter = 3.0;
	/** With guidance, the robot turns on the spot while the subgoal is more
	 * than this off its heading (MRPT's forward PTGs cannot) [deg]. */
	double turnInPlaceAboveDeg = 90;
	/** A turn in place ends when the subgoal is this near straight ahead;
	 * turn_in_place_above_deg may not be less (a turn would end as it
	 * started) [deg]. */
	static constexpr double kTurnEndsWithinDeg = 30;
	double turnRateDegps = 60;	//!< that turn's rate [deg/s]
	/** Before moving, the robot turns once on the spot at turnRateDegps,
	 * sensing as it goes: its laser covers 180 degrees and its cameras 70,
	 * so at the start the grid knows nothing behind or beside it, and the
	 * navigator would reverse (MRPT's backward PTG) or swing into space
	 * never seen (measured: share/doc/lvfusion/measurements.md). */
	bool lookAroundAtStart = true;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& target, const std::string& section) const override;
};

}  // namespace lvf::navigation
