// CHolonomicVFH, MRPT's holonomic-method interface to VFH+: the adapter from
// TP-obstacles, its log record through serialisation, and its options
// (strict INI, shipped defaults in share/lvfusion/config/vfh.ini).
//
// TP-space geometry used below: 121 directions, direction i at
// -180 + (i + 0.5) * 360/121 deg; window 1 and safety distance 0.025
// (normalised), so a TP-obstacle at 0.2 blocks the sector centres within
// asin(0.025/0.2) = 7.18 deg of it, with magnitude 2 - 0.2^2 / 1^2 = 1.96.

#include "CliTestSupport.h"

#include <gtest/gtest.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/plugin/registerAllClasses.h>
#include <lvfusion/vfh/CHolonomicVFH.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <memory>

using lvf::vfh::CHolonomicVFH;
using lvf::vfh::CLogFileRecord_VFH;
using mrpt::DEG2RAD;
using mrpt::RAD2DEG;

namespace
{
constexpr size_t kPaths = 121;

double pathAngleDeg(size_t i) { return -180.0 + (double(i) + 0.5) * 360.0 / double(kPaths); }

/** TP-obstacles: `near` for the paths within +-halfDeg of 0, else free. */
CHolonomicVFH::NavInput input(double near, double halfDeg, mrpt::math::TPoint2D target)
{
	CHolonomicVFH::NavInput ni;
	ni.obstacles.assign(kPaths, 1.0);
	for (size_t i = 0; i < kPaths; i++)
		if (std::abs(pathAngleDeg(i)) <= halfDeg) ni.obstacles[i] = near;
	ni.targets = {target};
	ni.maxRobotSpeed = 2.0;
	return ni;
}

/** The log record of one navigate() of a fresh method. */
std::shared_ptr<CLogFileRecord_VFH> logOf(const CHolonomicVFH::NavInput& ni)
{
	CHolonomicVFH vfh;
	CHolonomicVFH::NavOutput no;
	vfh.navigate(ni, no);
	return std::dynamic_pointer_cast<CLogFileRecord_VFH>(no.logRecord);
}

std::string dump(const mrpt::config::CLoadableOptions& o, const std::string& section)
{
	mrpt::config::CConfigFileMemory c;
	o.saveToConfigFile(c, section);
	return c.getContent();
}
}  // namespace

TEST(CHolonomicVfh, FreeTpSpaceHeadsStraightForTheTarget)
{
	CHolonomicVFH vfh;
	CHolonomicVFH::NavOutput no;
	vfh.navigate(input(1.0, 0, {0.5, 0.5}), no);
	EXPECT_NEAR(RAD2DEG(no.desiredDirection), 45.0, 1e-9);
	EXPECT_NEAR(no.desiredSpeed, 2.0, 1e-12) << "max speed: nothing ahead, target beyond the slow-down";
}

TEST(CHolonomicVfh, TpObstacleOnTheTargetSendsItRoundTheNearSide)
{
	// Paths within +-10 deg blocked at 0.2: the outermost at +-8.93 deg block
	// centres up to +-12.5 deg, the valleys start at +-17.5 deg, VFH+ steers
	// 8 sectors inside: +-57.5 deg; the target at atan(0.05/0.8) = 3.6 deg
	// makes the left one cheaper.
	CHolonomicVFH vfh;
	CHolonomicVFH::NavOutput no;
	vfh.navigate(input(0.2, 10.0, {0.8, 0.05}), no);
	EXPECT_NEAR(RAD2DEG(no.desiredDirection), 57.5, 1e-9);
	EXPECT_GT(no.desiredSpeed, 0.0);
}

TEST(CHolonomicVfh, TpObstacleBeyondTheTargetDoesNotBlockIt)
{
	// Paths within +-10 deg end at 0.2; the target straight ahead at 0.1,
	// before them: the window ends at 0.1 + 0.025, no cell is in it, and the
	// robot heads for the target (before the cut: the sectors within 12.5
	// deg blocked, steered off to +-57.5 deg, and near targets in rooms
	// circled, every sector with a wall within ref_distance being blocked).
	CHolonomicVFH vfh;
	CHolonomicVFH::NavOutput no;
	vfh.navigate(input(0.2, 10.0, {0.1, 0}), no);
	EXPECT_NEAR(RAD2DEG(no.desiredDirection), 0.0, 1e-9);
	const auto log = logOf(input(0.2, 10.0, {0.1, 0}));
	ASSERT_TRUE(log);
	for (double h : log->primaryHistogram) EXPECT_EQ(h, 0.0);
	// The same obstacles 0.02 behind the target are within its safety
	// distance: they still count.
	const auto near = logOf(input(0.12, 10.0, {0.1, 0}));
	ASSERT_TRUE(near);
	EXPECT_GT(near->primaryHistogram[36], 0.0);
}

TEST(CHolonomicVfh, TpObstacleCellsStopAtTheHorizon)
{
	const auto ni = input(0.2, 10.0, {0.8, 0});
	const size_t blocked = CHolonomicVFH::tpObstacleCells(ni).size();
	EXPECT_GT(blocked, 0u);
	EXPECT_EQ(CHolonomicVFH::tpObstacleCells(ni, 0.21).size(), blocked);
	EXPECT_EQ(CHolonomicVFH::tpObstacleCells(ni, 0.2).size(), 0u) << "a cell at the horizon is outside";
}

TEST(CHolonomicVfh, NarrowGapIsTakenWithAHalvedSafetyDistance)
{
	// Everything at 0.06 but the paths within +-15 deg (free): the nearest
	// blocked paths, at +-17.85 deg, enlarged by asin(0.025/0.06) = 24.6 deg
	// close the gap; with half the safety distance (12.0 deg) they block
	// down to +-5.85 deg, and the sectors centred at +-2.5 deg are free.
	auto ni = input(1.0, 0, {0.8, 0});
	for (size_t i = 0; i < kPaths; i++)
		if (std::abs(pathAngleDeg(i)) > 15.0) ni.obstacles[i] = 0.06;
	CHolonomicVFH vfh;
	CHolonomicVFH::NavOutput no;
	vfh.navigate(ni, no);
	EXPECT_NEAR(RAD2DEG(no.desiredDirection), 0.0, 2.5 + 1e-9);
	EXPECT_GT(no.desiredSpeed, 0.0);
	vfh.options.safetyFallback = false;
	vfh.navigate(ni, no);
	EXPECT_EQ(no.desiredSpeed, 0.0) << "VFH+ alone finds no valley";
}

TEST(CHolonomicVfh, SlowsDownNearTheTarget)
{
	CHolonomicVFH vfh;
	CHolonomicVFH::NavOutput no;
	vfh.navigate(input(1.0, 0, {0.05, 0}), no);
	EXPECT_NEAR(no.desiredSpeed, 2.0 * 0.05 / 0.10, 1e-12);
	vfh.enableApproachTargetSlowDown(false);
	vfh.navigate(input(1.0, 0, {0.05, 0}), no);
	EXPECT_NEAR(no.desiredSpeed, 2.0, 1e-12);
}

TEST(CHolonomicVfh, AllDirectionsBlockedStopsTheRobot)
{
	CHolonomicVFH vfh;
	CHolonomicVFH::NavOutput no;
	vfh.navigate(input(0.2, 180, {0.8, 0}), no);
	EXPECT_EQ(no.desiredSpeed, 0.0);
	const auto log = logOf(input(0.2, 180, {0.8, 0}));
	ASSERT_TRUE(log);
	EXPECT_FALSE(log->found);
}

TEST(CHolonomicVfh, LogRecordShowsTheHistogramPerPtgDirection)
{
	const auto log = logOf(input(0.2, 10.0, {0.8, 0.05}));
	ASSERT_TRUE(log);
	ASSERT_EQ(log->dirs_eval.size(), 3u);
	for (const auto& curve : log->dirs_eval)
	{
		ASSERT_EQ(curve.size(), kPaths);
		for (double v : curve) EXPECT_TRUE(v >= 0 && v <= 1) << v;
	}
	// Path 60 (0 deg) is blocked: density 1.96 > tau_high, so free-ness 0,
	// masked 0, score 0; path 100 (118.5 deg) is free and far from anything.
	EXPECT_EQ(log->dirs_eval[0][60], 0.0);
	EXPECT_EQ(log->dirs_eval[1][60], 0.0);
	EXPECT_EQ(log->dirs_eval[2][60], 0.0);
	EXPECT_EQ(log->dirs_eval[0][100], 1.0);
	EXPECT_EQ(log->dirs_eval[1][100], 1.0);
	EXPECT_GT(log->dirs_eval[2][100], 0.0);
	// Sector 36 (centre 2.5 deg) gets the TP-obstacles within 7.18 deg of it:
	// paths 59..63 (-2.98, 0, 2.98, 5.95, 8.93 deg), 1.96 each.
	EXPECT_NEAR(log->primaryHistogram[36], 5 * 1.96, 1e-9);
	EXPECT_NEAR(RAD2DEG(log->chosenDirection), 57.5, 1e-9);
}

TEST(CHolonomicVfh, LogRecordRoundTripsThroughSerialization)
{
	const auto original = logOf(input(0.2, 10.0, {0.8, 0.05}));
	ASSERT_TRUE(original);
	lvf::registerAllClasses();	// reading objects back finds classes by name

	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << *original;
	buf.Seek(0);
	const auto back = std::dynamic_pointer_cast<CLogFileRecord_VFH>(arch.ReadObject());
	ASSERT_TRUE(back);
	EXPECT_EQ(back->dirs_eval, original->dirs_eval);
	EXPECT_EQ(back->primaryHistogram, original->primaryHistogram);
	EXPECT_EQ(back->binaryHistogram, original->binaryHistogram);
	EXPECT_EQ(back->maskedHistogram, original->maskedHistogram);
	EXPECT_EQ(back->candidateDirections, original->candidateDirections);
	EXPECT_EQ(back->candidateCosts, original->candidateCosts);
	EXPECT_EQ(back->chosenDirection, original->chosenDirection);
	EXPECT_EQ(back->targetDirection, original->targetDirection);
	EXPECT_EQ(back->found, original->found);
	EXPECT_EQ(back->speedFactor, original->speedFactor);
	EXPECT_EQ(back->tauHigh, original->tauHigh);
}

TEST(CHolonomicVfh, MethodRoundTripsThroughSerialization)
{
	CHolonomicVFH vfh;
	vfh.options.vfh.mu1 = 7;
	vfh.options.targetSlowApproachingDistance = 0.3;
	lvf::registerAllClasses();
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << vfh;
	buf.Seek(0);
	const auto back = std::dynamic_pointer_cast<CHolonomicVFH>(arch.ReadObject());
	ASSERT_TRUE(back);
	EXPECT_EQ(dump(back->options, "s"), dump(vfh.options, "s"));
}

TEST(CHolonomicVfh, ShippedIniHoldsTheDefaults)
{
	// share/lvfusion/config/vfh.ini = a header + both sections as written by
	// saveToConfigFile; loading it changes nothing.
	const std::string path = std::string(LVF_SHARE_DIR) + "/config/vfh.ini";
	const std::string expected =
		dump(lvf::vfh::VfhParameters(), "VfhPlus") + dump(CHolonomicVFH::TOptions(), "CHolonomicVFH");
	EXPECT_EQ(lvf::test::keyLines(lvf::test::slurp(path)), lvf::test::keyLines(expected))
		<< "expected:\n" << expected;

	const auto cfg = lvf::common::openIniFile(path);
	lvf::vfh::VfhParameters engine;
	engine.loadFromConfigFile(*cfg, "VfhPlus");
	EXPECT_TRUE(engine == lvf::vfh::VfhParameters());
	CHolonomicVFH method(cfg.get());
	EXPECT_EQ(dump(method.options, "s"), dump(CHolonomicVFH::TOptions(), "s"));
}

TEST(CHolonomicVfh, OptionsRoundTripAndRefuseUnknownKeys)
{
	CHolonomicVFH::TOptions o;
	o.vfh.tauHigh = 2.5;
	o.vfh.wideValleySectors = 12;
	o.targetSlowApproachingDistance = 0.2;
	mrpt::config::CConfigFileMemory written;
	o.saveToConfigFile(written, "CHolonomicVFH");
	CHolonomicVFH::TOptions back;
	back.loadFromConfigFile(mrpt::config::CConfigFileMemory(written.getContent()), "CHolonomicVFH");
	EXPECT_EQ(dump(back, "s"), dump(o, "s"));

	// robot_radius belongs to the grid engine: in TP-space the PTG has the shape.
	mrpt::config::CConfigFileMemory bad("[CHolonomicVFH]\nrobot_radius = 0.3\n");
	try
	{
		CHolonomicVFH::TOptions().loadFromConfigFile(bad, "CHolonomicVFH");
		FAIL() << "no error";
	}
	catch (const lvf::common::InputError& e)
	{
		EXPECT_STREQ(e.what(), "<memory>: [CHolonomicVFH] robot_radius: unknown key");
	}
	mrpt::config::CConfigFileMemory badAngle("[VfhPlus]\nsector_angle_deg = 7\n");
	EXPECT_THROW(lvf::vfh::VfhParameters().loadFromConfigFile(badAngle, "VfhPlus"), lvf::common::InputError);
}
