#pragma once
// One closed-loop run of lvf-navigate, step by step (runNavigation's
// engine; private to libs/navigation).

#include <cmath>

#include <lvfusion/navigation/GlobalGuidance.h>
#include <lvfusion/navigation/NavigationRun.h>
#include <lvfusion/navigation/SimulatedRobotInterface.h>
#include <lvfusion/navigation/WorldCollision.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem.h>

#include <optional>
#include <vector>

namespace lvf::navigation
{
/** A pose with no NaN or infinity in it. */
inline bool finite(const mrpt::math::TPose2D& p)
{
	return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.phi);
}

/** One run, step by step: each control period the robot senses (every
 * `sensingEvery` steps), plans (with global guidance, every
 * `guidancePeriod`), drives (the first look around, a turn on the spot
 * towards a subgoal behind it, or MRPT's navigator), moves, and the world
 * judges where it got. Each stage that can end the run says so by
 * returning false, with the outcome written into the metrics. */
class ClosedLoop
{
   public:
	ClosedLoop(
		const NavigationScenario& scenario, const NavigationSetup& setup, const WorldCollision& collision,
		NavigationRun& run);

	/** Steps until the run has an outcome; fills the run's metrics. */
	void run();

   private:
	/** The sensors at the robot's pose, fused (or the laser alone), into the grids. */
	void sense();

	/** Plans on the robot's grid and steers along the plan. False (the run
	 * ends, `unreachable`) when no plan has been found for `unreachableAfter`. */
	bool followPlan();

	/** Sets m_lookAt to the first point of `path` within the unseen radius
	 * whose band column the cameras have not seen free, unless one near it
	 * was looked at already. */
	void lookBeforeGoing(const std::vector<mrpt::math::TPoint2D>& path);
	/** This step's command: the first look around, a turn on the spot, or
	 * MRPT's navigator. A subgoal behind the robot (the path turned back):
	 * MRPT's forward PTGs cannot turn in place and stall, or reverse blind;
	 * the robot turns on the spot until it faces the subgoal, then the
	 * navigator takes over again. */
	void drive();

	/** Where the step took the robot: a finite pose, clear of the world,
	 * and not yet at the target, or the run ends. */
	bool judgeMove();

	/** A navigator that stopped (subgoal reached or given up on) makes the
	 * guided loop plan again at the next step (the timeout still bounds
	 * the run); unguided, it ends the run. */
	bool navigatorGoesOn();

	/** Simulated time left before the timeout; false (the run ends,
	 * `timeout`) once it is up. */
	bool timeLeft();

	/** The navigator's target: the scenario's, or with global guidance a
	 * point of the planned path (an intermediary waypoint: no slowing down). */
	void steerAt(const mrpt::math::TPoint2D& p, bool isTarget);

	/** Bypasses the navigator for this step: turn at turnRate towards `side`'s sign. */
	void turnOnTheSpot(double side);

	const NavigationScenario& m_scenario;
	const NavigationSetup& m_setup;
	const NavigationLoopOptions& m_loop;
	const WorldCollision& m_collision;
	NavigationRun& m_run;
	NavigationMetrics& m_metrics;
	const bool m_fused, m_guided;

	lvf::simulation::CStereoLaserSimulator m_sim;
	lvf::fusion::CLaserStereoFusion m_fusion;
	mrpt::kinematics::CVehicleSimul_DiffDriven m_vehicle;
	SimulatedRobotInterface m_robot;
	mrpt::nav::CReactiveNavigationSystem m_navigator;
	GuidanceOptions m_guidance;

	mrpt::math::TPose2D m_pose;	 //!< the robot's true pose
	mrpt::math::TPoint2D m_subgoal;	 //!< what the navigator steers at
	bool m_subgoalIsTarget = true;
	double m_nextPlanTime = 0;	//!< plan at the first step
	double m_noPathSince = -1;	//!< <0: a path existed at the last plan
	bool m_turning = false;	 //!< turning in place towards the subgoal
	/** A point of the path the cameras have not seen through, to turn to
	 * before going on (guidanceUnseenRadius); the points looked at so far. */
	std::optional<mrpt::math::TPoint2D> m_lookAt;
	std::vector<mrpt::math::TPoint2D> m_lookedAt;
	double m_lookAroundLeft;  //!< [rad] of the first turn still to go
	const double m_turnRate;  //!< [rad/s]
};

}  // namespace lvf::navigation
