// CHolonomicVFH inside MRPT's own navigator, as MRPT tests its holonomic
// methods (libs/nav/src/reactive/rnav_unittest.cpp): a CReactiveNavigationSystem
// loaded from share/lvfusion/config/reactive_vfh.ini (holonomic_method =
// CHolonomicVFH, created by name from MRPT's class registry) drives MRPT's
// differential-drive simulator over a COccupancyGridMap2D with obstacles,
// sensing it with a simulated laser. Every target must be reached within
// 0.4 m, the navigator must never report NAV_ERROR, and the robot's
// footprint must never touch an obstacle.

#include "GridCourses.h"

#include <gtest/gtest.h>
#include <lvfusion/plugin/registerAllClasses.h>
#include <lvfusion/vfh/CHolonomicVFH.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/kinematics/CVehicleSimul_DiffDriven.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/nav/reactive/CLogFileRecord.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem.h>
#include <mrpt/nav/reactive/CRobot2NavInterfaceForSimulator.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <filesystem>
#include <ostream>
#include <unistd.h>

using mrpt::math::TPoint2D;
using mrpt::nav::CAbstractNavigator;

namespace
{
using lvf::test::Box;
using Scenario = lvf::test::Course;

/** The robot senses the grid with a 270 deg, 180-ray laser, as MRPT's test. */
class GridRobot : public mrpt::nav::CRobot2NavInterfaceForSimulator_DiffDriven
{
   public:
	GridRobot(mrpt::kinematics::CVehicleSimul_DiffDriven& sim, const mrpt::maps::COccupancyGridMap2D& grid)
		: CRobot2NavInterfaceForSimulator_DiffDriven(sim), m_grid(grid)
	{
		setMinLoggingLevel(mrpt::system::LVL_ERROR);
	}
	void sendNavigationStartEvent() override {}
	void sendNavigationEndEvent() override {}
	bool senseObstacles(mrpt::maps::CSimplePointsMap& obstacles, mrpt::system::TTimeStamp& t) override
	{
		mrpt::math::TPose2D pose, odometry;
		mrpt::math::TTwist2D vel;
		std::string frame;
		getCurrentPoseAndSpeeds(pose, vel, t, odometry, frame);
		mrpt::obs::CObservation2DRangeScan scan;
		scan.aperture = mrpt::DEG2RAD(270.0);
		scan.maxRange = 20.0;
		scan.sensorPose.z(0.4);	 // inside [min, max]_obstacles_height
		m_grid.laserScanSimulator(scan, mrpt::poses::CPose2D(pose), 0.4f, 180);
		obstacles.clear();
		obstacles.insertionOptions.minDistBetweenLaserPoints = 0;
		obstacles.loadFromRangeScan(scan);
		return true;
	}

   private:
	const mrpt::maps::COccupancyGridMap2D& m_grid;
};

/** MRPT's navigator set up from reactive_vfh.ini over a grid with the
 * scenario's obstacles, started towards its target. */
struct GridNavigation
{
	mrpt::maps::COccupancyGridMap2D grid{-10, 30, -10, 10, 0.10f};
	mrpt::kinematics::CVehicleSimul_DiffDriven sim;
	GridRobot robot{sim, grid};
	mrpt::nav::CReactiveNavigationSystem nav{robot, false /*console*/};
	std::vector<Box> obstacles;	 //!< as painted into the grid

	/** `navlogDir`: where to write a .reactivenavlog ("" = none). */
	explicit GridNavigation(const Scenario& s, const std::string& navlogDir = "")
	{
		lvf::registerAllClasses();
		obstacles = lvf::test::paintCourse(grid, s);

		nav.setMinLoggingLevel(mrpt::system::LVL_ERROR);
		nav.enableTimeLog(false);
		nav.enableKeepLogRecords(true);
		if (!navlogDir.empty())
		{
			nav.setLogFileDirectory(navlogDir);
			nav.enableLogFile(true);
		}
		nav.loadConfigFile(mrpt::config::CConfigFile(std::string(LVF_SHARE_DIR) + "/config/reactive_vfh.ini"));
		// MRPT caches the PTGs' collision grids as files: keep them out of
		// the working directory, in a folder of this process.
		const auto cache = std::filesystem::temp_directory_path() / ("lvf_vfh_ptgs_" + std::to_string(::getpid()));
		std::filesystem::create_directories(cache);
		nav.params_abstract_ptg_navigator.ptg_cache_files_directory = cache.string();
		nav.initialize();
		std::filesystem::remove_all(cache);

		CAbstractNavigator::TNavigationParams np;
		np.target.target_coords = mrpt::math::TPose2D(s.target.x, s.target.y, 0);
		np.target.targetAllowedDistance = 0.35f;
		nav.navigate(&np);
	}
	~GridNavigation()
	{
		// Keep MRPT's timing tables off the test output.
		const_cast<mrpt::system::CTimeLogger&>(nav.getTimeLogger()).clear(true);
		const_cast<mrpt::system::CTimeLogger&>(nav.getDelaysTimeLogger()).clear(true);
	}
};

class ReactiveNavWithVfh : public ::testing::TestWithParam<Scenario>
{
};
}  // namespace

TEST_P(ReactiveNavWithVfh, ReachesTargetWithoutErrorOrCollision)
{
	const Scenario& s = GetParam();
	GridNavigation run(s);
	auto& nav = run.nav;
	auto& sim = run.sim;

	// The footprint of reactive_vfh.ini (x -0.2..0.1, y -0.1..0.1 m), its
	// outline sampled every 1 cm: the gap to the nearest obstacle box.
	std::vector<TPoint2D> outline;
	const TPoint2D corners[] = {{-0.2, 0.1}, {0.1, 0.1}, {0.1, -0.1}, {-0.2, -0.1}};
	for (int c = 0; c < 4; c++)
		for (int j = 0; j < 30; j++)
		{
			const TPoint2D &a = corners[c], &b = corners[(c + 1) % 4];
			outline.push_back(a + (b - a) * (j / 30.0));
		}
	double clearance = 1e9;
	bool vfhLogged = false;
	for (int i = 0; i < 600; i++)
	{
		nav.navigationStep();
		ASSERT_NE(nav.getCurrentState(), CAbstractNavigator::NAV_ERROR) << "step " << i;
		if (!vfhLogged)
		{
			mrpt::nav::CLogFileRecord rec;
			nav.getLastLogRecord(rec);
			for (const auto& info : rec.infoPerPTG)
				if (auto vfh = std::dynamic_pointer_cast<lvf::vfh::CLogFileRecord_VFH>(info.HLFR))
				{
					vfhLogged = true;
					ASSERT_EQ(vfh->dirs_eval.size(), 3u);
					EXPECT_EQ(vfh->dirs_eval[0].size(), 121u) << "one value per PTG path";
					EXPECT_EQ(vfh->primaryHistogram.size(), 72u);
				}
		}
		if (nav.getCurrentState() == CAbstractNavigator::IDLE) break;
		sim.simulateOneTimeStep(0.2);
		const mrpt::math::TPose2D pose = sim.getCurrentGTPose();
		for (const auto& local : outline)
		{
			const TPoint2D q = pose.composePoint(local);
			for (const auto& b : run.obstacles) clearance = std::min(clearance, b.distance(q));
		}
	}
	EXPECT_TRUE(vfhLogged) << "the navigator ran CHolonomicVFH";
	EXPECT_EQ(nav.getCurrentState(), CAbstractNavigator::IDLE);
	const auto p = sim.getCurrentGTPose();
	EXPECT_LT((TPoint2D(p.x, p.y) - s.target).norm(), 0.4);
	if (!s.obstacles.empty()) { EXPECT_GT(clearance, 0.0); }
	RecordProperty("final_distance_m", std::to_string((TPoint2D(p.x, p.y) - s.target).norm()));
	RecordProperty("min_clearance_m", std::to_string(clearance));
}

INSTANTIATE_TEST_SUITE_P(
	Targets, ReactiveNavWithVfh,
	::testing::Values(
		// MRPT's own two cases (rnav_unittest.cpp):
		Scenario{"FreeSpace", {2.0, 0.4}, {}},
		Scenario{"BlockBeside", {9.0, 4.0}, {{{4.0, -2.0}, {5.0, 2.0}}}},
		// The target straight behind a wall: a detour is the only way.
		Scenario{"BehindWall", {6.0, 0.0}, {{{3.0, -1.5}, {3.4, 1.5}}}},
		// Through a 1.2 m gap between two blocks; the straight line to the
		// target runs into the lower one.
		Scenario{"ThroughGap", {8.0, -1.5}, {{{4.0, -4.0}, {4.5, 0.4}}, {{4.0, 1.6}, {4.5, 6.0}}}}),
	[](const auto& info) { return info.param.name; });

TEST(CHolonomicVfh, CreatedByNameFromMrptRegistry)
{
	lvf::registerAllClasses();
	const auto method = mrpt::nav::CAbstractHolonomicReactiveMethod::Factory("CHolonomicVFH");
	ASSERT_TRUE(method);
	EXPECT_TRUE(std::dynamic_pointer_cast<lvf::vfh::CHolonomicVFH>(method));
}

TEST(ReactiveNavLog, NavlogHoldsVfhRecordsNavlogViewerCanDraw)
{
	// What navlog-viewer does with a .reactivenavlog (once the plugin has
	// registered the classes): read CLogFileRecord objects and, per PTG, draw
	// HLFR->dirs_eval curves that have one value per TP-obstacle.
	const auto dir = std::filesystem::temp_directory_path() / ("lvf_vfh_navlog_" + std::to_string(::getpid()));
	std::filesystem::remove_all(dir);
	std::filesystem::create_directories(dir);
	{
		GridNavigation run(Scenario{"BehindWall", {6.0, 0.0}, {{{3.0, -1.5}, {3.4, 1.5}}}}, dir.string());
		for (int i = 0; i < 10; i++)
		{
			run.nav.navigationStep();
			run.sim.simulateOneTimeStep(0.2);
		}
	}  // closes the log
	std::vector<std::filesystem::path> logs;
	for (const auto& e : std::filesystem::directory_iterator(dir))
		if (e.path().extension() == ".reactivenavlog") logs.push_back(e.path());
	ASSERT_EQ(logs.size(), 1u);

	mrpt::io::CFileGZInputStream in(logs[0].string());
	auto arch = mrpt::serialization::archiveFrom(in);
	size_t records = 0, vfhRecords = 0;
	for (;;)
	{
		mrpt::serialization::CSerializable::Ptr obj;
		try
		{
			obj = arch.ReadObject();
		}
		catch (const mrpt::serialization::CExceptionEOF&)
		{
			break;
		}
		const auto rec = std::dynamic_pointer_cast<mrpt::nav::CLogFileRecord>(obj);
		ASSERT_TRUE(rec);
		records++;
		for (const auto& info : rec->infoPerPTG)
		{
			const auto vfh = std::dynamic_pointer_cast<lvf::vfh::CLogFileRecord_VFH>(info.HLFR);
			if (!vfh) continue;
			vfhRecords++;
			ASSERT_FALSE(vfh->dirs_eval.empty());
			for (const auto& curve : vfh->dirs_eval) EXPECT_EQ(curve.size(), info.TP_Obstacles.size());
		}
	}
	EXPECT_EQ(records, 10u);
	// Steps that keep following the last command (MRPT's "NOP") run no
	// holonomic method, the others run it for each PTG that can reach the
	// target: at least one step must have.
	EXPECT_GE(vfhRecords, 1u);
	std::filesystem::remove_all(dir);
}
