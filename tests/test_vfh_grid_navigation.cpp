// The grid engine VfhPlus in closed loop, as the paper uses VFH (§6): every
// cycle the active window of an occupancy grid around the robot gives a
// steering direction and a speed; a B21r-like robot (turns on the spot,
// radius 0.26 m) turns towards the direction at a bounded rate and drives.
// Every target must be reached within 0.4 m, and the robot's body must never
// overlap an occupied cell.

#include "GridCourses.h"

#include <gtest/gtest.h>
#include <lvfusion/vfh/VfhPlus.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

using mrpt::math::TPoint2D;

namespace
{
using lvf::test::Course;

class VfhGridNavigation : public ::testing::TestWithParam<Course>
{
};
}  // namespace

TEST_P(VfhGridNavigation, ReachesTargetWithoutTouchingObstacles)
{
	const Course& c = GetParam();
	mrpt::maps::COccupancyGridMap2D grid(-3, 10, -5, 5, 0.10f);
	const auto obstacles = lvf::test::paintCourse(grid, c);

	lvf::vfh::VfhPlus vfh;	// published / documented defaults, metres
	const double dt = 0.1, vMax = 0.6, omegaMax = mrpt::DEG2RAD(120.0);
	TPoint2D p(0, 0);
	double heading = 0, clearance = 1e9;
	int cycles = 0;
	for (; cycles < 1000 && (c.target - p).norm() > 0.3; cycles++)
	{
		const double toTarget = std::atan2(c.target.y - p.y, c.target.x - p.x);
		const auto r = vfh.step(lvf::vfh::activeWindow(grid, p, vfh.parameters().windowRadius), toTarget, heading);
		ASSERT_TRUE(r.found) << "boxed in at cycle " << cycles;
		// Turn towards the chosen direction at most omegaMax; VFH's speed
		// law, reduced while turning (VFH 1991: V = V'(1 - omega/omega_max))
		// and near the target.
		const double turn = std::clamp(mrpt::math::wrapToPi(r.direction - heading), -omegaMax * dt, omegaMax * dt);
		heading = mrpt::math::wrapToPi(heading + turn);
		const double v = vMax * r.speedFactor * (1.0 - std::abs(turn) / (omegaMax * dt)) *
			std::min(1.0, (c.target - p).norm() / 0.5);
		p += TPoint2D(std::cos(heading), std::sin(heading)) * (v * dt);
		// The round body (radius 0.26 m) against the boxes.
		for (const auto& b : obstacles)
			clearance = std::min(clearance, b.distance(p) - vfh.parameters().robotRadius);
	}
	EXPECT_LT((c.target - p).norm(), 0.4) << "stopped at " << p.asString() << " after " << cycles << " cycles";
	if (!c.obstacles.empty()) { EXPECT_GT(clearance, 0.0); }
	RecordProperty("cycles", cycles);
	RecordProperty("min_body_clearance_m", std::to_string(clearance));
}

INSTANTIATE_TEST_SUITE_P(
	Courses, VfhGridNavigation,
	::testing::Values(
		Course{"FreeSpace", {5.0, 2.0}, {}},
		// Straight behind a 3 m wall: round either end.
		Course{"BehindWall", {6.0, 0.0}, {{{3.0, -1.5}, {3.3, 1.5}}}},
		// Through a 1.2 m gap between two walls; the straight line to the
		// target runs into the lower one.
		Course{"ThroughGap", {7.0, -2.0}, {{{3.0, -4.0}, {3.3, -0.1}}, {{3.0, 1.1}, {3.3, 4.0}}}},
		// Boxes in the way.
		Course{"Clutter", {8.0, 1.0},
			   {{{1.5, -0.6}, {2.0, 0.4}}, {{3.5, 0.5}, {4.0, 2.0}}, {{4.5, -1.5}, {5.0, -0.2}}, {{6.0, 0.3}, {6.5, 1.5}}}}),
	[](const auto& info) { return info.param.name; });
