#include "ClosedLoop.h"
#include "SeenRays.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/navigation/HolonomicMethods.h>
#include <lvfusion/navigation/NavigatorConfig.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/kinematics/CVehicleVelCmd_DiffDriven.h>
#include <mrpt/math/CPolygon.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/system/CTicTac.h>

#include <algorithm>
#include <cmath>

namespace lvf::navigation
{
using lvf::fusion::CLaserStereoFusion;

namespace
{
/** A path point within this of one already looked at is not looked at again [m]. */
constexpr double kLookedAtRadius = 0.3;
/** A look ends when the point is this near the heading (the cameras see 35 degrees to each side). */
constexpr double kLookedWithin = 10 * M_PI / 180;
/** The navigator does not sense an overhang's assumed far part within the
 * robot's radius + this of the robot, or of a path the plan had to lay
 * through it [m]: VFH+ grows obstacles by the radius + its safety distance
 * (0.1 m), and cells that near would block every direction. */
constexpr double kAssumedFreeMargin = 0.1;

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

}  // namespace

ClosedLoop::ClosedLoop(
	const NavigationScenario& scenario, const NavigationSetup& setup, const WorldCollision& collision,
	NavigationRun& run)
	: m_scenario(scenario),
	  m_setup(setup),
	  m_loop(setup.loop),
	  m_collision(collision),
	  m_run(run),
	  m_metrics(run.metrics),
	  m_fused(setup.sensing == Sensing::Fused),
	  m_guided(setup.loop.globalGuidance),
	  m_sim(scenario.world, setup.sensors),
	  m_fusion(setup.fusion),
	  m_robot(m_vehicle, *run.grid, setup.loop.obstacleRange),
	  m_navigator(m_robot, false, false),
	  m_pose(scenario.start),
	  m_subgoal(scenario.target),
	  m_lookAroundLeft(setup.loop.lookAroundAtStart ? 2 * M_PI : 0),
	  m_turnRate(mrpt::DEG2RAD(setup.loop.turnRateDegps))
{
	m_vehicle.setCurrentGTPose(scenario.start);
	m_robot.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	// A frame the fusion cannot trust (a table top right in front hides the
	// floor it judges the calibration by, README) falls back to the laser,
	// and the grids take that into account; a line per such frame would
	// bury a batch's table.
	m_fusion.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	mrpt::config::CConfigFileMemory config(setup.navigatorConfig);
	config.write("CAbstractPTGBasedReactive", "holonomic_method", setup.method);
	quietNavigator(m_navigator);
	m_navigator.setLogFileDirectory(setup.navigatorLogDir);
	m_navigator.enableLogFile(!setup.navigatorLogDir.empty());
	try
	{
		m_navigator.loadConfigFile(config);
		// Not read from the INI by MRPT 2.5: set after loading.
		m_navigator.params_abstract_ptg_navigator.ptg_cache_files_directory = setup.ptgCacheDir;
		m_navigator.changeRobotShape(robotShape(scenario.world.robot.radius));
		// Builds the PTGs' tables, where MRPT asserts on their parameters.
		m_navigator.initialize();
	}
	catch (const std::exception& e)
	{
		throw navigatorRefuses(setup.navigatorConfigSource, e);
	}

	m_guidance.robotRadius = scenario.world.robot.radius;
	m_guidance.clearance = m_loop.guidanceClearance;
	m_guidance.overhangDepth = m_loop.guidanceOverhangDepth;
	m_guidance.lookahead = m_loop.guidanceLookahead;
	if (m_fused && (m_loop.guidanceUnseenRadius > 0 || m_loop.guidanceOverhangUnseen))
	{
		m_run.grid->trackSeenSpace(setup.fusion.band);
		m_run.grid->seenSpace()->markFree(mrpt::math::TPoint2D(scenario.start), m_loop.startSeenRadius);
	}
	if (m_fused && m_loop.guidanceOverhangUnseen) m_run.grid->assumeOverhangsWhereUnseen(m_loop.unseenMinHeight);
	if (m_fused && m_loop.guidanceUnseenRadius > 0)
	{
		m_guidance.unseenRadius = m_loop.guidanceUnseenRadius;
		m_guidance.unseenFrom = m_loop.guidanceUnseenFrom;
		m_guidance.unseenMinHeight = m_loop.unseenMinHeight;
	}
	m_guidance.occupiedBelow = m_loop.occupiedBelow;
	if (!m_guided) steerAt(scenario.target, true);
}

void ClosedLoop::run()
{
	m_metrics.trajectory.push_back(m_pose);
	m_metrics.minClearance = m_collision.clearance(mrpt::math::TPoint2D(m_pose)).distance;
	double cycleSeconds = 0;
	mrpt::system::CTicTac timer;
	for (size_t cycle = 0;; cycle++)
	{
		timer.Tic();
		if (cycle % size_t(m_loop.sensingEvery) == 0) sense();
		if (m_guided && m_metrics.time >= m_nextPlanTime - 1e-9 && !followPlan()) break;
		drive();
		m_vehicle.simulateOneTimeStep(m_loop.controlPeriod);
		cycleSeconds += timer.Tac();
		m_metrics.cycles++;
		m_metrics.time += m_loop.controlPeriod;
		if (!judgeMove() || !navigatorGoesOn() || !timeLeft()) break;
	}
	m_metrics.meanCycleMs = 1e3 * cycleSeconds / double(std::max<size_t>(1, m_metrics.cycles));
}

void ClosedLoop::sense()
{
	auto& m = m_metrics;
	const double t = m_setup.sensors.startTime + m.time;
	const auto frame = m_sim.simulateAt(m.sensingUpdates++, mrpt::poses::CPose2D(m_pose), t, m_fused, false);
	CLaserStereoFusion::Result r;
	if (!m_fused)
		r = CLaserStereoFusion::laserOnly(*frame.scan, "laser-only run");
	else
	{
		try
		{
			r = m_fusion.process(
				*frame.scan, *frame.stereo, mrpt::format("%s: t=%.1f s", m_scenario.world.name.c_str(), m.time),
				m_loop.fusionPointMemory ? std::optional<mrpt::poses::CPose2D>(m_pose) : std::nullopt);
		}
		catch (const lvf::common::InputError& e)
		{
			r = CLaserStereoFusion::laserOnly(*frame.scan, e.what());
		}
	}
	const mrpt::poses::CPose2D at(m_pose);
	m_run.grid->insertLaser(*frame.scan, at);
	if (m_fused && !r.fellBackToLaser)
		m_run.grid->insertVision(*inCameraView(*r.fused, *frame.stereo, m_setup.fusion), at);
	if (m_loop.navigatorKeepsOffAssumed || m_loop.guidanceOverhangUnseen)
		m_run.grid->markTraversed(at, m_scenario.world.robot.radius);
	if (auto* seen = m_run.grid->seenSpace())
	{
		if (!r.fellBackToLaser) carveSeenRays(r, at, *seen);
		seen->markFree(mrpt::math::TPoint2D(m_pose), m_scenario.world.robot.radius);
	}
	if (m_setup.onSensing) m_setup.onSensing(frame, r);
}

bool ClosedLoop::followPlan()
{
	auto& m = m_metrics;
	m_nextPlanTime = m.time + m_loop.guidancePeriod;
	const auto g = planGuidance(*m_run.grid, mrpt::math::TPoint2D(m_pose), m_scenario.target, m_guidance);
	m.plans++;
	if (m_loop.navigatorKeepsOffAssumed && g.status != Guidance::Status::Unreachable)
	{
		// Only round a path that keeps its full clearance off them: in a
		// narrower way VFH+ (which grows every cell by the radius and its
		// safety distance) would find no valley between them and the walls.
		// Where the plan goes through them, its path stays open; and none
		// round the robot itself (it may have come among them while the
		// plan went through them): they would box it in.
		// Nor round the target, as far as the robot must come to it: the
		// plan may end short of it, on a cell it could reach.
		const double clearance = m_guidance.robotRadius + kAssumedFreeMargin;
		const bool wide = g.status == Guidance::Status::Path && g.clearance >= m_guidance.clearance;
		std::vector<LocalObstacleGrid::Disk> open{{m_scenario.target, clearance + m_loop.targetTolerance}};
		if (!g.keepsOffAssumed)
			for (const auto& p : g.path) open.push_back({p, clearance});
		m_run.grid->senseAssumedOverhangs(wide ? m_guidance.overhangDepth : 0, std::move(open), clearance);
	}
	if (g.status != Guidance::Status::Unreachable)
	{
		m_noPathSince = -1;
		if (g.status == Guidance::Status::Path)
		{
			steerAt(g.subgoal, g.subgoalIsTarget), m_run.plannedPath = g.path;
			// A path through columns the cameras have not seen through: look first.
			if (!g.keepsOffAssumed && m_guidance.unseenRadius > 0) lookBeforeGoing(g.path);
		}
		else steerAt(m_scenario.target, true);
		return true;
	}
	if (m_noPathSince < 0) m_noPathSince = m.time;
	if (m.time - m_noPathSince >= m_loop.unreachableAfter - 1e-9)
	{
		m.outcome = Outcome::Unreachable;
		m.finalDistance = std::hypot(m_pose.x - m_scenario.target.x, m_pose.y - m_scenario.target.y);
		m.detail = mrpt::format(
			"the target is unreachable: %s for %.1f s (at %.2f m from it after %.1f s)", g.detail.c_str(),
			m.time - m_noPathSince, m.finalDistance, m.time);
		return false;
	}
	if (m.plans == 1) steerAt(m_scenario.target, true);	 // nothing better yet
	return true;
}

void ClosedLoop::lookBeforeGoing(const std::vector<mrpt::math::TPoint2D>& path)
{
	const mrpt::math::TPoint2D here(m_pose);
	for (const auto& p : path)
	{
		const double d = std::hypot(p.x - here.x, p.y - here.y);
		if (d > m_guidance.unseenRadius) return;
		if (d < m_guidance.unseenFrom || !m_run.grid->unseen(p.x, p.y, m_guidance.unseenMinHeight)) continue;
		// Once per place: what a look cannot show (too near, above the
		// view) must not stop the robot for good.
		for (const auto& q : m_lookedAt)
			if (std::hypot(p.x - q.x, p.y - q.y) < kLookedAtRadius) return;
		m_lookAt = p;
		m_lookedAt.push_back(p);
		return;
	}
}

void ClosedLoop::drive()
{
	const double bearing =
		mrpt::math::wrapToPi(std::atan2(m_subgoal.y - m_pose.y, m_subgoal.x - m_pose.x) - m_pose.phi);
	if (m_lookAt && m_lookAroundLeft <= 0)
	{
		const double toLook =
			mrpt::math::wrapToPi(std::atan2(m_lookAt->y - m_pose.y, m_lookAt->x - m_pose.x) - m_pose.phi);
		if (std::abs(toLook) > kLookedWithin)
		{
			turnOnTheSpot(toLook);
			m_turning = true;
			return;
		}
		m_lookAt.reset();
		m_nextPlanTime = m_metrics.time + m_loop.controlPeriod;  // plan on what the look saw
	}
	if (m_lookAroundLeft > 0)
	{
		turnOnTheSpot(+1);
		m_lookAroundLeft -= m_turnRate * m_loop.controlPeriod;
		// Plan afresh on what the turn saw, and start the navigator then.
		if (m_lookAroundLeft <= 0) m_nextPlanTime = m_metrics.time + m_loop.controlPeriod, m_turning = true;
	}
	else if (m_guided && std::abs(bearing) > mrpt::DEG2RAD(m_turning ? NavigationLoopOptions::kTurnEndsWithinDeg : m_loop.turnInPlaceAboveDeg))
	{
		turnOnTheSpot(bearing);
		m_turning = true;
	}
	else
	{
		if (m_turning) steerAt(m_subgoal, m_subgoalIsTarget);	// a fresh start from the new heading
		m_turning = false;
		m_navigator.navigationStep();
	}
}

bool ClosedLoop::judgeMove()
{
	auto& m = m_metrics;
	const auto next = m_vehicle.getCurrentGTPose();
	if (!finite(next))
	{
		m.outcome = Outcome::InvalidPose;
		m.detail = "the robot's pose became " + next.asString();
		return false;
	}
	m.pathLength += std::hypot(next.x - m_pose.x, next.y - m_pose.y);
	const mrpt::math::TPoint2D stepStart(m_pose);
	m_pose = next;
	m.trajectory.push_back(m_pose);
	m.finalDistance = std::hypot(m_pose.x - m_scenario.target.x, m_pose.y - m_scenario.target.y);
	const auto c = m_collision.clearance(mrpt::math::TPoint2D(m_pose));
	if (c.distance < m.minClearance)
	{
		m.minClearance = c.distance;
		m.minClearanceBox = c.box >= 0 ? m_collision.boxName(c.box) : "";
	}
	if (c.distance < 0)
	{
		m.outcome = Outcome::Collision;
		m.collisions = 1;
		m.detail = mrpt::format(
			"hit '%s' at (%.2f, %.2f) after %.1f s", m_collision.boxName(c.box).c_str(), m_pose.x, m_pose.y,
			m.time);
		return false;
	}
	if (m.finalDistance <= m_loop.targetTolerance)
	{
		m.pathLength -= stepLengthInsideCircle(
			stepStart, mrpt::math::TPoint2D(m_pose), m_scenario.target, m_loop.targetTolerance);
		m.outcome = Outcome::Reached;
		m.detail = mrpt::format("reached the target after %.1f s", m.time);
		return false;
	}
	return true;
}

namespace
{
/** MRPT's navigator catches the exceptions of its own step (a
 * configuration only checked then, such as a scalar_score_formula that
 * does not compile) and stops as in an emergency: no replanning mends
 * that, every step would fail the same way. MRPT 2.5 keeps the reason
 * while a new navigate() call (the plan's next subgoal) sets the state
 * back to NAVIGATING, so the reason is what tells. */
bool failedWithin(const mrpt::nav::CAbstractNavigator::TErrorReason& reason)
{
	return reason.error_code == mrpt::nav::CAbstractNavigator::TErrorCode::ERR_EMERGENCY_STOP &&
		reason.error_msg.find("exception") != std::string::npos;
}
}  // namespace

bool ClosedLoop::navigatorGoesOn()
{
	auto& m = m_metrics;
	const auto& reason = m_navigator.getErrorReason();
	if (failedWithin(reason))
	{
		m.outcome = Outcome::NavigatorError;
		m.detail = mrpt::format("the navigator failed after %.1f s: %s", m.time,
			lvf::common::exceptionMessage(std::runtime_error(reason.error_msg)).c_str());
		return false;
	}
	const auto state = m_navigator.getCurrentState();
	if (state != mrpt::nav::CAbstractNavigator::NAV_ERROR && state != mrpt::nav::CAbstractNavigator::IDLE)
		return true;
	if (m_guided)
	{
		m_nextPlanTime = m.time;
		return true;
	}
	m.outcome = Outcome::NavigatorError;
	m.detail = mrpt::format(
		"the navigator stopped %.2f m from the target after %.1f s: %s", m.finalDistance, m.time,
		reason.error_msg.empty() ? "(no reason given)" : reason.error_msg.c_str());
	return false;
}

bool ClosedLoop::timeLeft()
{
	auto& m = m_metrics;
	if (m.time < m_loop.timeout - 1e-9) return true;
	m.outcome = Outcome::Timeout;
	m.detail = mrpt::format("still %.2f m from the target after %.1f s", m.finalDistance, m.time);
	return false;
}

void ClosedLoop::steerAt(const mrpt::math::TPoint2D& p, bool isTarget)
{
	mrpt::nav::CAbstractNavigator::TNavigationParams goal;
	goal.target.target_coords = mrpt::math::TPose2D(p.x, p.y, 0);
	goal.target.targetAllowedDistance = float(m_loop.targetTolerance);
	goal.target.targetIsIntermediaryWaypoint = !isTarget;
	if (!isTarget) goal.target.targetDesiredRelSpeed = subgoalRelativeSpeed(m_setup.method);
	m_navigator.navigate(&goal);
	m_subgoal = p;
	m_subgoalIsTarget = isTarget;
}

void ClosedLoop::turnOnTheSpot(double side)
{
	mrpt::kinematics::CVehicleVelCmd_DiffDriven cmd;
	cmd.ang_vel = std::copysign(m_turnRate, side);
	m_robot.changeSpeeds(cmd);
}

}  // namespace lvf::navigation
