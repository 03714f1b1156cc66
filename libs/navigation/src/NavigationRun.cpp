#include <lvfusion/common/InputError.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/navigation/GlobalGuidance.h>
#include <lvfusion/navigation/HolonomicMethods.h>
#include <lvfusion/navigation/NavigationRun.h>
#include <lvfusion/navigation/NavigatorConfig.h>
#include <lvfusion/navigation/SimulatedRobotInterface.h>
#include <lvfusion/navigation/WorldCollision.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/math/CPolygon.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem.h>
#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <cmath>

namespace lvf::navigation
{
using lvf::fusion::CLaserStereoFusion;
using lvf::simulation::CStereoLaserSimulator;

const char* sensingName(Sensing s) { return s == Sensing::Fused ? "fused" : "laser"; }

Sensing parseSensing(const std::string& name, const std::string& source)
{
	if (name == "fused") return Sensing::Fused;
	if (name == "laser") return Sensing::Laser;
	throw lvf::common::InputError(source, "", "'" + name + "' is not a sensing mode (fused, laser)");
}

namespace
{
/** A turn in place ends when the subgoal is this near straight ahead [rad]. */
constexpr double kTurnUntil = M_PI / 6;

bool finite(const mrpt::math::TPose2D& p)
{
	return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.phi);
}

/** The robot's cylinder as the polygon the PTGs check against: a 16-gon
 * around the circle (circumscribed, so the polygon never under-covers it). */
mrpt::math::CPolygon robotShape(double radius)
{
	constexpr int n = 16;
	const double r = radius / std::cos(M_PI / n);
	mrpt::math::CPolygon shape;
	for (int i = 0; i < n; i++)
		shape.AddVertex(r * std::cos(2 * M_PI * i / n), r * std::sin(2 * M_PI * i / n));
	return shape;
}

/** The fused scan with the bearings the cameras do not see made invalid:
 * there it is only the laser again, which must not clear vision's cells.
 * "See" is some height of the band at the bearing's range: with the camera
 * tilted down, a bearing at the image's side can clear a floating box
 * above the part of the column in view (room 50 with overhangs). Requiring
 * the whole column was measured and not kept: a collision in one of 200
 * rooms and in the box room (share/doc/lvfusion/measurements.md,
 * lvf-navigate). */
mrpt::obs::CObservation2DRangeScan::Ptr inCameraView(
	const mrpt::obs::CObservation2DRangeScan& fusedScan,
	const mrpt::obs::CObservationStereoImages& stereo,
	const lvf::fusion::CLaserStereoFusion::TOptions& fusion)
{
	auto out = std::make_shared<mrpt::obs::CObservation2DRangeScan>(fusedScan);
	std::vector<float> ranges(fusedScan.getScanSize());
	for (size_t i = 0; i < ranges.size(); i++)
		ranges[i] = fusedScan.getScanRangeValidity(i) ? fusedScan.getScanRange(i) : INFINITY;
	const auto inView = lvf::metrics::bearingsInView(fusedScan, ranges, stereo, fusion.band, fusion.depth.zMax);
	for (size_t i = 0; i < ranges.size(); i++)
		if (!inView[i]) out->setScanRangeValidity(i, false);
	return out;
}

/** Checks a scenario can be run at all; fills `m` and returns false if not. */
bool checkScenario(const NavigationScenario& s, const WorldCollision& collision, NavigationMetrics& m)
{
	if (!finite(s.start) || !std::isfinite(s.target.x) || !std::isfinite(s.target.y))
	{
		m.outcome = Outcome::InvalidPose;
		m.detail = "start " + s.start.asString() + " or target " + s.target.asString() + " is not finite";
		return false;
	}
	if (const auto c = collision.clearance(mrpt::math::TPoint2D(s.start)); c.distance < 0)
	{
		m.outcome = Outcome::StartInCollision;
		m.minClearance = c.distance;
		m.detail = mrpt::format("the robot starts %.3f m into '%s'", -c.distance, collision.boxName(c.box).c_str());
		return false;
	}
	if (const auto c = collision.clearance(s.target); c.distance < 0)
	{
		m.outcome = Outcome::TargetInObstacle;
		m.detail = mrpt::format("the robot cannot stand at the target: %.3f m into '%s'", -c.distance, collision.boxName(c.box).c_str());
		return false;
	}
	return true;
}

}  // namespace

NavigationRun runNavigation(const NavigationScenario& scenario, const NavigationSetup& setup)
{
	NavigationRun run;
	auto& m = run.metrics;
	const auto& world = scenario.world;
	const auto& loop = setup.loop;
	const WorldCollision collision(world, world.robot);
	if (!checkScenario(scenario, collision, m)) return run;

	double xMin, xMax, yMin, yMax;
	world.footprintBounds(xMin, xMax, yMin, yMax, 1.0);
	// The grid holds the start and the target too: a target beyond the
	// world's walls is still a cell the planner can find closed off.
	for (const auto& p : {mrpt::math::TPoint2D(scenario.start), scenario.target})
	{
		xMin = std::min(xMin, p.x - 1.0), xMax = std::max(xMax, p.x + 1.0);
		yMin = std::min(yMin, p.y - 1.0), yMax = std::max(yMax, p.y + 1.0);
	}
	run.grid = std::make_unique<LocalObstacleGrid>(
		xMin, xMax, yMin, yMax, loop.gridResolution, loop.occupiedBelow);
	CStereoLaserSimulator sim(world, setup.sensors);
	CLaserStereoFusion fusion(setup.fusion);
	mrpt::kinematics::CVehicleSimul_DiffDriven vehicle;
	vehicle.setCurrentGTPose(scenario.start);
	SimulatedRobotInterface robot(vehicle, *run.grid, loop.obstacleRange);
	robot.setMinLoggingLevel(mrpt::system::LVL_ERROR);

	mrpt::config::CConfigFileMemory config(setup.navigatorConfig);
	config.write("CAbstractPTGBasedReactive", "holonomic_method", setup.method);
	mrpt::nav::CReactiveNavigationSystem navigator(robot, false, false);
	quietNavigator(navigator);
	navigator.setLogFileDirectory(setup.navigatorLogDir);
	navigator.enableLogFile(!setup.navigatorLogDir.empty());
	navigator.loadConfigFile(config);
	// Not read from the INI by MRPT 2.5: set after loading.
	navigator.params_abstract_ptg_navigator.ptg_cache_files_directory = setup.ptgCacheDir;
	navigator.changeRobotShape(robotShape(world.robot.radius));
	navigator.initialize();

	// The navigator's target: the scenario's, or with global guidance a
	// point of the planned path (an intermediary waypoint: no slowing down).
	mrpt::math::TPoint2D subgoal = scenario.target;
	bool subgoalIsTarget = true;
	const auto steerAt = [&](const mrpt::math::TPoint2D& p, bool isTarget) {
		mrpt::nav::CAbstractNavigator::TNavigationParams goal;
		goal.target.target_coords = mrpt::math::TPose2D(p.x, p.y, 0);
		goal.target.targetAllowedDistance = float(loop.targetTolerance);
		goal.target.targetIsIntermediaryWaypoint = !isTarget;
		if (!isTarget) goal.target.targetDesiredRelSpeed = subgoalRelativeSpeed(setup.method);
		navigator.navigate(&goal);
		subgoal = p;
		subgoalIsTarget = isTarget;
	};
	const bool guided = loop.globalGuidance;
	GuidanceOptions guidance;
	guidance.robotRadius = world.robot.radius;
	guidance.clearance = loop.guidanceClearance;
	guidance.overhangDepth = loop.guidanceOverhangDepth;
	guidance.lookahead = loop.guidanceLookahead;
	guidance.occupiedBelow = loop.occupiedBelow;
	double nextPlanTime = 0;  // plan at the first step
	double noPathSince = -1;  // <0: a path existed at the last plan
	bool turning = false;  // turning in place towards the subgoal
	double lookAroundLeft = loop.lookAroundAtStart ? 2 * M_PI : 0;  // [rad] of the first turn
	const double turnRate = mrpt::DEG2RAD(loop.turnRateDegps);	// [rad/s]
	// Bypasses the navigator for this step: turn at turnRate towards `side`'s sign.
	const auto turnOnTheSpot = [&](double side) {
		mrpt::kinematics::CVehicleVelCmd_DiffDriven cmd;
		cmd.ang_vel = std::copysign(turnRate, side);
		robot.changeSpeeds(cmd);
	};
	if (!guided) steerAt(scenario.target, true);

	const bool fused = setup.sensing == Sensing::Fused;
	mrpt::math::TPose2D pose = scenario.start;
	m.trajectory.push_back(pose);
	m.minClearance = collision.clearance(mrpt::math::TPoint2D(pose)).distance;
	double cycleSeconds = 0;
	mrpt::system::CTicTac timer;
	for (size_t cycle = 0;; cycle++)
	{
		timer.Tic();
		if (cycle % size_t(loop.sensingEvery) == 0)
		{
			const double t = setup.sensors.startTime + m.time;
			const auto frame = sim.simulateAt(m.sensingUpdates++, mrpt::poses::CPose2D(pose), t, fused, false);
			CLaserStereoFusion::Result r;
			if (!fused)
				r = CLaserStereoFusion::laserOnly(*frame.scan, "laser-only run");
			else
			{
				try
				{
					r = fusion.process(*frame.scan, *frame.stereo, mrpt::format("%s: t=%.1f s", world.name.c_str(), m.time));
				}
				catch (const lvf::common::InputError& e)
				{
					r = CLaserStereoFusion::laserOnly(*frame.scan, e.what());
				}
			}
			const mrpt::poses::CPose2D at(pose);
			run.grid->insertLaser(*frame.scan, at);
			if (fused && !r.fellBackToLaser)
				run.grid->insertVision(*inCameraView(*r.fused, *frame.stereo, setup.fusion), at);
			if (setup.onSensing) setup.onSensing(frame, r);
		}
		if (guided && m.time >= nextPlanTime - 1e-9)
		{
			nextPlanTime = m.time + loop.guidancePeriod;
			const auto g = planGuidance(*run.grid, mrpt::math::TPoint2D(pose), scenario.target, guidance);
			m.plans++;
			if (g.status == Guidance::Status::Unreachable)
			{
				if (noPathSince < 0) noPathSince = m.time;
				if (m.time - noPathSince >= loop.unreachableAfter - 1e-9)
				{
					m.outcome = Outcome::Unreachable;
					m.finalDistance = std::hypot(pose.x - scenario.target.x, pose.y - scenario.target.y);
					m.detail = mrpt::format(
						"the target is unreachable: %s for %.1f s (at %.2f m from it after %.1f s)",
						g.detail.c_str(), m.time - noPathSince, m.finalDistance, m.time);
					break;
				}
				if (m.plans == 1) steerAt(scenario.target, true);  // nothing better yet
			}
			else
			{
				noPathSince = -1;
				if (g.status == Guidance::Status::Path) steerAt(g.subgoal, g.subgoalIsTarget), run.plannedPath = g.path;
				else steerAt(scenario.target, true);
			}
		}
		// A subgoal behind the robot (the path turned back): MRPT's forward
		// PTGs cannot turn in place and stall, or reverse blind; the robot
		// turns on the spot until it faces the subgoal, then the navigator
		// takes over again.
		const double bearing = mrpt::math::wrapToPi(std::atan2(subgoal.y - pose.y, subgoal.x - pose.x) - pose.phi);
		if (lookAroundLeft > 0)
		{
			turnOnTheSpot(+1);
			lookAroundLeft -= turnRate * loop.controlPeriod;
			// Plan afresh on what the turn saw, and start the navigator then.
			if (lookAroundLeft <= 0) nextPlanTime = m.time + loop.controlPeriod, turning = true;
		}
		else if (guided && std::abs(bearing) > (turning ? kTurnUntil : mrpt::DEG2RAD(loop.turnInPlaceAboveDeg)))
		{
			turnOnTheSpot(bearing);
			turning = true;
		}
		else
		{
			if (turning) steerAt(subgoal, subgoalIsTarget);	 // a fresh start from the new heading
			turning = false;
			navigator.navigationStep();
		}
		vehicle.simulateOneTimeStep(loop.controlPeriod);
		cycleSeconds += timer.Tac();
		m.cycles++;
		m.time += loop.controlPeriod;

		const auto next = vehicle.getCurrentGTPose();
		if (!finite(next))
		{
			m.outcome = Outcome::InvalidPose;
			m.detail = "the robot's pose became " + next.asString();
			break;
		}
		m.pathLength += std::hypot(next.x - pose.x, next.y - pose.y);
		const mrpt::math::TPoint2D stepStart(pose);
		pose = next;
		m.trajectory.push_back(pose);
		m.finalDistance = std::hypot(pose.x - scenario.target.x, pose.y - scenario.target.y);
		const auto c = collision.clearance(mrpt::math::TPoint2D(pose));
		if (c.distance < m.minClearance)
		{
			m.minClearance = c.distance;
			m.minClearanceBox = c.box >= 0 ? collision.boxName(c.box) : "";
		}
		if (c.distance < 0)
		{
			m.outcome = Outcome::Collision;
			m.collisions = 1;
			m.detail = mrpt::format(
				"hit '%s' at (%.2f, %.2f) after %.1f s", collision.boxName(c.box).c_str(), pose.x, pose.y, m.time);
			break;
		}
		if (m.finalDistance <= loop.targetTolerance)
		{
			m.pathLength -= stepLengthInsideCircle(
				stepStart, mrpt::math::TPoint2D(pose), scenario.target, loop.targetTolerance);
			m.outcome = Outcome::Reached;
			m.detail = mrpt::format("reached the target after %.1f s", m.time);
			break;
		}
		const auto state = navigator.getCurrentState();
		const bool stopped = state == mrpt::nav::CAbstractNavigator::NAV_ERROR || state == mrpt::nav::CAbstractNavigator::IDLE;
		if (stopped && guided)
		{
			// A subgoal reached or given up on: plan again at the next step
			// (the timeout still bounds the run).
			if (state == mrpt::nav::CAbstractNavigator::NAV_ERROR) m.navigatorErrors++;
			nextPlanTime = m.time;
		}
		else if (stopped)
		{
			m.outcome = Outcome::NavigatorError;
			const auto& why = navigator.getErrorReason().error_msg;
			m.detail = mrpt::format(
				"the navigator stopped %.2f m from the target after %.1f s: %s", m.finalDistance, m.time,
				why.empty() ? "(no reason given)" : why.c_str());
			break;
		}
		if (m.time >= loop.timeout - 1e-9)
		{
			m.outcome = Outcome::Timeout;
			m.detail = mrpt::format("still %.2f m from the target after %.1f s", m.finalDistance, m.time);
			break;
		}
	}
	m.meanCycleMs = 1e3 * cycleSeconds / double(std::max<size_t>(1, m.cycles));
	return run;
}

}  // namespace lvf::navigation
