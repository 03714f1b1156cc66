// WorldCollision against hand-computed geometry: the robot is a cylinder of
// radius r up to height h; every solid between the floor and h can be hit.

#include <lvfusion/navigation/WorldCollision.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <gtest/gtest.h>

#include <cmath>

using lvf::navigation::WorldCollision;
using mrpt::math::TPoint2D;

namespace
{
lvf::simulation::World world(const std::string& boxes)
{
	return lvf::simulation::parseWorld(
		"name: t\nrobot: {radius: 0.3, height: 1.2, obstacle_min_height: 0.05}\npath: {poses: [[0, 0, 0]]}\nboxes:\n" + boxes,
		"<test>");
}
}  // namespace

TEST(WorldCollision, DistanceToAnAxisAlignedBox)
{
	// A 1 x 2 m box centred at (2, 0): faces at x = 1.5 / 2.5, y = -1 / 1.
	const auto w = world("  - {name: b, pose: [2, 0, 0], size: [1, 2, 0.5]}\n");
	const WorldCollision c(w, w.robot);
	EXPECT_NEAR(c.clearance(TPoint2D(0, 0)).distance, 1.5 - 0.3, 1e-9);  // facing the x face
	EXPECT_NEAR(c.clearance(TPoint2D(2, 3)).distance, 2.0 - 0.3, 1e-9);  // facing the y face
	EXPECT_NEAR(c.clearance(TPoint2D(3.5, 2)).distance, std::hypot(1.0, 1.0) - 0.3, 1e-9);  // a corner
	EXPECT_NEAR(c.clearance(TPoint2D(1.3, 0)).distance, -0.1, 1e-9);  // 0.1 m into it
	EXPECT_TRUE(c.collides(TPoint2D(2, 0)));
	EXPECT_FALSE(c.collides(TPoint2D(1.19, 0)));
	EXPECT_EQ(c.clearance(TPoint2D(0, 0)).box, 0);
}

TEST(WorldCollision, YawedBox)
{
	// A 2 x 0.2 m plank turned 90 degrees at the origin: it spans y in [-1, 1],
	// x in [-0.1, 0.1]. A point at (1, 0) is 0.9 m from it; at (0, 1.5), 0.5 m.
	const auto w = world("  - {name: plank, pose: [0, 0, 90], size: [2, 0.2, 1]}\n");
	const WorldCollision c(w, w.robot);
	EXPECT_NEAR(c.clearance(TPoint2D(1, 0)).distance, 0.9 - 0.3, 1e-9);
	EXPECT_NEAR(c.clearance(TPoint2D(0, 1.5)).distance, 0.5 - 0.3, 1e-9);
}

TEST(WorldCollision, TableTopAboveTheLaserStillHitsTheRobot)
{
	// A table top at 0.7 m (the laser scans at ~0.3 m and never sees it) over
	// the robot's path: the 1.2 m tall robot hits it; a shelf at 1.4 m does not.
	const auto w = world(
		"  - {name: top, pose: [2, 0, 0], size: [1, 1, 0.04], elevation: 0.7}\n"
		"  - {name: high, pose: [5, 0, 0], size: [1, 1, 0.3], elevation: 1.4}\n");
	const WorldCollision c(w, w.robot);
	EXPECT_TRUE(c.collides(TPoint2D(2, 0)));
	EXPECT_NEAR(c.clearance(TPoint2D(1.2, 0)).distance, 0.0, 1e-9);  // edge at 1.5: touching
	EXPECT_NEAR(c.clearance(TPoint2D(1.1, 0)).distance, 0.4 - 0.3, 1e-9);
	EXPECT_FALSE(c.collides(TPoint2D(5, 0)));
	EXPECT_NEAR(c.clearance(TPoint2D(5, 0)).distance, 3.0 - 0.5 - 0.3, 1e-9);  // only the table counts
	EXPECT_EQ(c.boxName(c.clearance(TPoint2D(5, 0)).box), "top");
}

TEST(WorldCollision, NothingToHit)
{
	const auto w = world("  - {name: high, pose: [0, 0, 0], size: [1, 1, 0.3], elevation: 1.3}\n");
	const WorldCollision c(w, w.robot);
	EXPECT_TRUE(std::isinf(c.clearance(TPoint2D(0, 0)).distance));
	EXPECT_EQ(c.clearance(TPoint2D(0, 0)).box, -1);
}
