#include <lvfusion/common/IniSection.h>
#include <lvfusion/navigation/NavigationLoopOptions.h>

namespace lvf::navigation
{
using lvf::common::writeOption;

void NavigationLoopOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	controlPeriod = ini.real("control_period", controlPeriod, 1e-3, 10);
	sensingEvery = ini.integer("sensing_every", sensingEvery, 1, 1000);
	timeout = ini.real("timeout", timeout, 0.1, 1e6);
	targetTolerance = ini.real("target_tolerance", targetTolerance, 0.01, 10);
	gridResolution = ini.real("grid_resolution", gridResolution, 0.01, 1);
	obstacleRange = ini.real("obstacle_range", obstacleRange, 0.1, 100);
	occupiedBelow = ini.real("occupied_below", occupiedBelow, 0.01, 0.99);
	visionObstacleMargin = ini.real("vision_obstacle_margin", visionObstacleMargin, 0, 2);
	fusionPointMemory = ini.flag("fusion_point_memory", fusionPointMemory);
	globalGuidance = ini.flag("global_guidance", globalGuidance);
	guidancePeriod = ini.real("guidance_period", guidancePeriod, 1e-3, 1e6);
	guidanceLookahead = ini.real("guidance_lookahead", guidanceLookahead, 0.1, 100);
	guidanceClearance = ini.real("guidance_clearance", guidanceClearance, 0, 10);
	guidanceOverhangDepth = ini.real("guidance_overhang_depth", guidanceOverhangDepth, 0, 10);
	navigatorKeepsOffAssumed = ini.flag("navigator_keeps_off_assumed", navigatorKeepsOffAssumed);
	guidanceOverhangUnseen = ini.flag("guidance_overhang_unseen", guidanceOverhangUnseen);
	guidanceUnseenRadius = ini.real("guidance_unseen_radius", guidanceUnseenRadius, 0, 100);
	guidanceUnseenFrom = ini.real("guidance_unseen_from", guidanceUnseenFrom, 0, 100);
	unseenMinHeight = ini.real("unseen_min_height", unseenMinHeight, 0, 10);
	startSeenRadius = ini.real("start_seen_radius", startSeenRadius, 0, 100);
	unreachableAfter = ini.real("unreachable_after", unreachableAfter, 0, 1e6);
	turnInPlaceAboveDeg = ini.real("turn_in_place_above_deg", turnInPlaceAboveDeg, kTurnEndsWithinDeg, 180);
	turnRateDegps = ini.real("turn_rate_degps", turnRateDegps, 1, 720);
	lookAroundAtStart = ini.flag("look_around_at_start", lookAroundAtStart);
	ini.rejectUnknownKeys();
}

void NavigationLoopOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "control_period", controlPeriod, "one navigation step and robot motion [s]");
	writeOption(c, s, "sensing_every", sensingEvery, "sense, fuse and update the grid every this many steps");
	writeOption(c, s, "timeout", timeout, "simulated time before the run is given up [s]");
	writeOption(c, s, "target_tolerance", targetTolerance, "target reached when this close [m]");
	writeOption(c, s, "grid_resolution", gridResolution, "local occupancy grid cell size [m]");
	writeOption(c, s, "obstacle_range", obstacleRange, "occupied cells this near the robot are obstacles for the navigator [m]");
	writeOption(c, s, "occupied_below", occupiedBelow, "a cell is occupied when its free probability is below this [0-1]");
	writeOption(c, s, "vision_obstacle_margin", visionObstacleMargin, "the navigator also senses the cells this near an obstacle only vision found (its edges are less sure than the laser's; a floating box's unseen sides go on past them); 0: off [m]");
	writeOption(c, s, "fusion_point_memory", fusionPointMemory, "fused runs: give the fusion the robot's pose so that its memory of earlier frames' points ([VisualPointMemory]) works (false: the local grid is the loop's memory)");
	writeOption(c, s, "global_guidance", globalGuidance, "plan by value iteration on the robot's grid and steer along the path (false: straight at the target)");
	writeOption(c, s, "guidance_period", guidancePeriod, "replan this often, and whenever the subgoal is reached [s]");
	writeOption(c, s, "guidance_lookahead", guidanceLookahead, "the navigator's subgoal is at most this far along the planned path, in straight sight [m]");
	writeOption(c, s, "guidance_clearance", guidanceClearance, "the path keeps this much more than the robot radius off obstacles (retried with half, then 0, if no path) [m]");
	writeOption(c, s, "guidance_overhang_depth", guidanceOverhangDepth, "the plan keeps off cells vision never looked at within this distance of an obstacle only vision found: an overhang's unseen far part (with the full, then half the clearance; dropped if both close every way; 0: off) [m]");
	writeOption(c, s, "navigator_keeps_off_assumed", navigatorKeepsOffAssumed, "while the plan keeps off those assumed cells at its full clearance, the navigator senses them as obstacles too (it cuts the path's corners, and round a floating box's unseen side the corner is the box)");
	writeOption(c, s, "guidance_overhang_unseen", guidanceOverhangUnseen, "fused runs: those assumed cells also include the ones vision's 2D grid calls free but whose band column the cameras have not seen through (a ray under a floating box clears its cells in 2D; unseen_min_height)");
	writeOption(c, s, "guidance_unseen_radius", guidanceUnseenRadius, "fused runs: the plan also keeps off cells this near the robot whose band column the cameras have not seen free (dropped with the overhang depth if that closes every way; 0: off) [m]");
	writeOption(c, s, "guidance_unseen_from", guidanceUnseenFrom, "with guidance_unseen_radius: cells nearer the robot than this are left alone (the cameras never see the whole band there) [m]");
	writeOption(c, s, "unseen_min_height", unseenMinHeight, "a cell's column is unseen when at least this much of the band over it has not been seen free [m]");
	writeOption(c, s, "start_seen_radius", startSeenRadius, "with guidance_unseen_radius or guidance_overhang_unseen: the disk round the start taken as seen free (the cameras cannot see the whole band that near) [m]");
	writeOption(c, s, "unreachable_after", unreachableAfter, "no path on the grid for this long ends the run as unreachable [s]");
	writeOption(c, s, "turn_in_place_above_deg", turnInPlaceAboveDeg, "with guidance: turn on the spot while the subgoal is more than this off the heading [deg]");
	writeOption(c, s, "turn_rate_degps", turnRateDegps, "rate of that turn [deg/s]");
	writeOption(c, s, "look_around_at_start", lookAroundAtStart, "turn once on the spot, sensing, before moving (the sensors see nothing behind the robot)");
}

}  // namespace lvf::navigation
