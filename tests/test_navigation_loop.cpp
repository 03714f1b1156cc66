// The closed loop against simulator truth: the box room of Fig. 7 is crossed
// without touching anything when vision is fused, and scenarios that cannot
// succeed end with the outcome that says why, within the time bound.

#include <lvfusion/common/InputError.h>
#include <lvfusion/navigation/HolonomicMethods.h>
#include <lvfusion/navigation/NavigationRun.h>
#include <lvfusion/navigation/RandomScenario.h>
#include <lvfusion/navigation/WorldCollision.h>
#include <lvfusion/planning/ValueIterationPlanner.h>
#include <lvfusion/plugin/registerAllClasses.h>
#include <lvfusion/simulation/GroundTruth.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <gtest/gtest.h>

#include "TestWorlds.h"

#include <cmath>
#include <filesystem>
#include <mrpt/config/CConfigFileMemory.h>

#include <algorithm>
#include <fstream>
#include <sstream>

namespace nav = lvf::navigation;
using nav::Outcome;

namespace
{
std::string shippedNavigatorConfig()
{
	std::ifstream in(std::string(LVF_SHARE_DIR) + "/config/navigate.ini");
	std::stringstream s;
	s << in.rdbuf();
	return s.str();
}

nav::NavigationScenario boxRoom()
{
	nav::NavigationScenario s;
	s.world = lvf::simulation::loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml");
	s.start = s.world.path.front();
	s.target = *s.world.target;
	return s;
}

class NavigationLoop : public ::testing::Test
{
   protected:
	void SetUp() override
	{
		lvf::registerAllClasses();
		m_dir = std::filesystem::temp_directory_path() /
			("lvf_nav_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
		std::filesystem::create_directories(m_dir);
	}
	void TearDown() override { std::filesystem::remove_all(m_dir); }

	nav::NavigationSetup setup(nav::Sensing sensing, const std::string& method = "CHolonomicND") const
	{
		nav::NavigationSetup s;
		s.method = method;
		s.sensing = sensing;
		s.navigatorConfig = shippedNavigatorConfig();
		// The fusion as lvf-navigate runs it: navigate.ini's search options.
		s.fusion.depth.loadFromConfigFile(mrpt::config::CConfigFileMemory(s.navigatorConfig), "FocusedEpipolarSearch");
		s.ptgCacheDir = m_dir.string();
		return s;
	}

	std::filesystem::path m_dir;
};

/** Recomputes the run's clearance from its trajectory, independently of the
 * loop's own bookkeeping. */
double minClearanceOf(const nav::NavigationScenario& s, const nav::NavigationMetrics& m)
{
	const nav::WorldCollision c(s.world, s.world.robot);
	double best = INFINITY;
	for (const auto& p : m.trajectory) best = std::min(best, c.clearance(mrpt::math::TPoint2D(p)).distance);
	return best;
}

}  // namespace

// The paper's point, measured: in the box room of Fig. 7 the laser alone
// drives into a box floating above its plane; with vision fused the robot
// does not touch anything. (MRPT's ND does not reach the far corner, it
// stalls in the clutter; CHolonomicVFH does, next test.)
TEST_F(NavigationLoop, BoxRoomLaserOnlyHitsAnOverhangFusedDoesNot)
{
	const auto scenario = boxRoom();
	auto cfg = setup(nav::Sensing::Laser);
	cfg.loop.timeout = 25;
	const auto laser = nav::runNavigation(scenario, cfg).metrics;
	EXPECT_EQ(laser.outcome, Outcome::Collision) << laser.detail;
	EXPECT_EQ(laser.collisions, 1);
	EXPECT_EQ(laser.minClearanceBox.rfind("float_", 0), 0u) << laser.minClearanceBox;	// above the laser plane
	EXPECT_LT(minClearanceOf(scenario, laser), 0.0);

	cfg.sensing = nav::Sensing::Fused;
	const auto fused = nav::runNavigation(scenario, cfg).metrics;
	EXPECT_EQ(fused.collisions, 0) << fused.detail;
	EXPECT_NE(fused.outcome, Outcome::Collision);
	EXPECT_GT(minClearanceOf(scenario, fused), 0.0);
	EXPECT_NEAR(minClearanceOf(scenario, fused), fused.minClearance, 1e-9);
	// It went somewhere: past where the laser-only run hit.
	EXPECT_GT(fused.pathLength, laser.pathLength);
}

// Issue 4: with vision fused, our VFH+ crosses the box room of Fig. 7 to its
// target, guided, without touching anything (measured: reached after 42 s
// of simulated time; README, lvf-navigate).
TEST_F(NavigationLoop, BoxRoomFusedVfhReachesTheTarget)
{
	const auto scenario = boxRoom();
	auto cfg = setup(nav::Sensing::Fused, "CHolonomicVFH");
	cfg.loop.timeout = 60;
	const auto m = nav::runNavigation(scenario, cfg).metrics;
	EXPECT_EQ(m.outcome, Outcome::Reached) << m.detail;
	EXPECT_EQ(m.collisions, 0) << m.detail;
	EXPECT_GT(minClearanceOf(scenario, m), 0.0);
	EXPECT_LE(m.finalDistance, cfg.loop.targetTolerance);
}

// With the plan keeping off what the cameras have not seen through the band
// (guidance_unseen_radius, off by default), as measured, with both search
// options: the run still reaches, and its 3D memory holds float_a, 0.6-1.0 m
// over the floor, as not seen through. (Measured before narrow gaps were
// closed, so with them open. With them closed this combination took another
// way and touched float_d after 42.7 s, clearance -0.005 m -- the loop's
// known weakness, a floating box's side the cameras did not see on a changed
// route; the shipped loop reaches, the test above.)
TEST_F(NavigationLoop, BoxRoomWithTheUnseenGuardReachesAndRemembersTheOverhang)
{
	const auto scenario = boxRoom();
	auto cfg = setup(nav::Sensing::Fused, "CHolonomicVFH");
	cfg.loop.timeout = 60;
	cfg.loop.guidanceUnseenRadius = 1.5;
	cfg.fusion.depth.shiftedWindows = true;
	cfg.fusion.depth.subpixelIterations = 2;
	cfg.fusion.fusion.bridgeWidth = 0;
	// The range rules of when this guard was measured (ScanFusion.h): with
	// today's (central_share 0.15, range_support 0.03 m) the robot takes
	// another route here and stands 0.94 m short of the target at 60 s.
	cfg.fusion.fusion.centralShare = 0;
	cfg.fusion.fusion.rangeSupport = 0;
	// And the model of then: with segment ends joined (ModelWalls.h) the
	// route changes again and brushes a box (7 mm deep).
	cfg.fusion.joinSegmentEnds = 0;
	const auto run = nav::runNavigation(scenario, cfg);
	const auto& m = run.metrics;
	EXPECT_EQ(m.outcome, Outcome::Reached) << m.detail;
	EXPECT_EQ(m.collisions, 0) << m.detail;
	EXPECT_GT(minClearanceOf(scenario, m), 0.0);
	ASSERT_NE(run.grid->seenSpace(), nullptr);
	const auto& floatA = *std::find_if(
		scenario.world.boxes.begin(), scenario.world.boxes.end(), [](const auto& b) { return b.name == "float_a"; });
	EXPECT_GE(run.grid->seenSpace()->unseenHeight(floatA.x, floatA.y), 0.3);
}

TEST_F(NavigationLoop, StartInCollisionIsReportedWithoutRunning)
{
	auto s = boxRoom();
	s.start = mrpt::math::TPose2D(2.2, 2.6, 0);	// inside floor_a
	const auto m = nav::runNavigation(s, setup(nav::Sensing::Laser)).metrics;
	EXPECT_EQ(m.outcome, Outcome::StartInCollision);
	EXPECT_EQ(m.cycles, 0u);
	EXPECT_NE(m.detail.find("floor_a"), std::string::npos) << m.detail;
}

TEST_F(NavigationLoop, TargetInsideAnObstacleIsReportedWithoutRunning)
{
	auto s = boxRoom();
	s.target = mrpt::math::TPoint2D(3.6, 2.4);	// under float_a (0.6 .. 1.0 m up)
	const auto m = nav::runNavigation(s, setup(nav::Sensing::Laser)).metrics;
	EXPECT_EQ(m.outcome, Outcome::TargetInObstacle);
	EXPECT_EQ(m.cycles, 0u);
	EXPECT_NE(m.detail.find("float_a"), std::string::npos) << m.detail;
}

TEST_F(NavigationLoop, NaNPoseIsReportedWithoutRunning)
{
	auto s = boxRoom();
	s.start.x = std::nan("");
	EXPECT_EQ(nav::runNavigation(s, setup(nav::Sensing::Laser)).metrics.outcome, Outcome::InvalidPose);
	s = boxRoom();
	s.target.y = INFINITY;
	EXPECT_EQ(nav::runNavigation(s, setup(nav::Sensing::Laser)).metrics.outcome, Outcome::InvalidPose);
	// Finite, but farther than a grid could reach, or than a run could plan
	// on ((900, 900): 3e8 cells, 3.7 s a control step and 6 GB before the
	// check): not run either.
	for (const double xy : {1e300, 900.0})
	{
		s = boxRoom();
		s.target = {xy, xy};
		const auto farOff = nav::runNavigation(s, setup(nav::Sensing::Laser)).metrics;
		EXPECT_EQ(farOff.outcome, Outcome::InvalidPose) << xy;
		EXPECT_EQ(farOff.cycles, 0u);
		EXPECT_NE(farOff.detail.find("that the robot's grids would need"), std::string::npos) << farOff.detail;
	}
	// 100 m off is a run (about 4 million cells).
	s = boxRoom();
	s.target = {100, 3};
	auto quick = setup(nav::Sensing::Laser);
	quick.loop.timeout = 0.3;
	EXPECT_EQ(nav::runNavigation(s, quick).metrics.outcome, Outcome::Timeout);
}

TEST_F(NavigationLoop, UnreachableTargetEndsWithinTheTimeBoundWithoutCollision)
{
	// A closed, empty 6 x 6 m room (inner faces x = -1, 5; y = -3, 3), the
	// robot at the origin, the target 3 m beyond the east wall.
	nav::NavigationScenario s;
	s.world = lvf::test::worldFromText(lvf::test::roomWorld(""));
	s.start = s.world.path.front();
	s.target = mrpt::math::TPoint2D(8.0, 0.0);
	auto cfg = setup(nav::Sensing::Laser);
	cfg.loop.timeout = 30;
	const auto m = nav::runNavigation(s, cfg).metrics;
	// Global guidance finds every way out walled in once the robot has seen
	// the room: "unreachable", well before the timeout.
	EXPECT_EQ(m.outcome, Outcome::Unreachable) << nav::outcomeName(m.outcome) << ": " << m.detail;
	EXPECT_NE(m.detail.find("no collision-free path"), std::string::npos) << m.detail;
	EXPECT_LT(m.time, 30 - 1.0);
	// Without guidance the navigator alone can only time out or give up.
	cfg.loop.globalGuidance = false;
	const auto reactive = nav::runNavigation(s, cfg).metrics;
	EXPECT_TRUE(reactive.outcome == Outcome::Timeout || reactive.outcome == Outcome::NavigatorError) << nav::outcomeName(reactive.outcome);
	EXPECT_LE(reactive.time, 30 + 1e-6);
	EXPECT_EQ(reactive.collisions, 0) << reactive.detail;
	// It cannot get nearer than the wall's inner face less its radius.
	EXPECT_GE(m.finalDistance, 3.0 + s.world.robot.radius - 1e-6);
	EXPECT_EQ(m.collisions, 0) << m.detail;
}

TEST(HolonomicMethods, FoundByNameInMrptsRegistry)
{
	lvf::registerAllClasses();
	for (const char* name : {"CHolonomicND", "CHolonomicVFF", "CHolonomicFullEval"})
		EXPECT_NO_THROW(nav::requireHolonomicMethod(name, "--method")) << name;
	EXPECT_THROW(nav::requireHolonomicMethod("CHolonomicNope", "--method"), lvf::common::InputError);
	// Registered, but not a holonomic method.
	EXPECT_THROW(nav::requireHolonomicMethod("CPose2D", "--method"), lvf::common::InputError);
}

TEST(RandomScenario, EveryRoomHasAReachableTarget)
{
	// Clutter walled the far corner in for overhang rooms 17 and 34 (the
	// robot can stand there, but no way leads there): the target moves along
	// the far wall to a place a way leads to. Room 50 was closed from wall to
	// wall: it is drawn again from its seed's next stream (same name, other
	// clutter). Checked on the world's true obstacles in the robot's band,
	// grown by its radius (the scenario asks 0.1 m more), for the rooms the
	// README's batches run.
	lvf::planning::ValueIterationPlanner::TOptions o;
	for (uint32_t seed = 1; seed <= 100; seed++)
	{
		const auto s = nav::randomScenario(seed, nav::RoomKind::Overhangs);
		o.robotRadius = s.world.robot.radius;
		EXPECT_TRUE(lvf::planning::ValueIterationPlanner(o)
						.plan(lvf::simulation::obstacleGrid(s.world, 0.05, 0.5), {s.start.x, s.start.y}, s.target)
						.found())
			<< s.world.name;
		EXPECT_GT(nav::WorldCollision(s.world, s.world.robot).clearance(s.target).distance, 0.1) << s.world.name;
		EXPECT_EQ(s.world.name, "overhangs_" + std::to_string(seed));
	}
}
