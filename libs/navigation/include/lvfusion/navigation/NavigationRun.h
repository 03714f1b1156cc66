#pragma once
// The closed loop (issue 4): at a fixed control period, the simulator renders
// the sensors at the robot's true pose, the fusion (or the laser alone)
// updates the local occupancy grid, MRPT's CReactiveNavigationSystem with the
// chosen holonomic method steers, and MRPT's differential-drive simulator
// moves the robot. Collisions are judged against the full 3D world
// (WorldCollision), not against what the sensors saw.
//
// Localisation is taken as perfect (the grid is built at the true pose): the
// paper's robot localised against a map, and this loop measures obstacle
// avoidance, not odometry drift.

#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/navigation/LocalObstacleGrid.h>
#include <lvfusion/navigation/NavigationLoopOptions.h>
#include <lvfusion/navigation/NavigationOutcome.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>

#include <functional>
#include <memory>

namespace lvf::navigation
{
enum class Sensing
{
	Fused,	//!< laser + stereo, the paper's fusion
	Laser  //!< the laser scan alone
};
const char* sensingName(Sensing s);
/** "fused" / "laser"; throws InputError naming `source` otherwise. */
Sensing parseSensing(const std::string& name, const std::string& source);

struct NavigationScenario
{
	lvf::simulation::World world;
	mrpt::math::TPose2D start;
	mrpt::math::TPoint2D target;
};

struct NavigationSetup
{
	std::string method = "CHolonomicND";  //!< a registered holonomic method
	Sensing sensing = Sensing::Fused;
	/** MRPT reactive navigation INI text (PTGs, method parameters...). */
	std::string navigatorConfig;
	/** Where navigatorConfig came from, for error messages. */
	std::string navigatorConfigSource = "navigator configuration";
	NavigationLoopOptions loop;
	lvf::simulation::CStereoLaserSimulator::TOptions sensors;
	lvf::fusion::CLaserStereoFusion::TOptions fusion;
	/** Folder for MRPT's PTG look-up tables: computing them takes seconds,
	 * so runs sharing the folder start faster. Must exist. */
	std::string ptgCacheDir = ".";
	/** Folder for MRPT's navigation log (log_NNN.reactivenavlog, for
	 * MRPT's navlog-viewer); empty: no log. Must exist. */
	std::string navigatorLogDir;
	/** Called after every sensing update (e.g. to write the run's rawlog). */
	std::function<void(
		const lvf::simulation::CStereoLaserSimulator::Frame&,
		const lvf::fusion::CLaserStereoFusion::Result&)>
		onSensing;
};

struct NavigationRun
{
	NavigationMetrics metrics;
	/** The robot's grid at the end (null if the run never started). */
	std::unique_ptr<LocalObstacleGrid> grid;
	/** The last path global guidance planned (empty without guidance). */
	std::vector<mrpt::math::TPoint2D> plannedPath;
};

/** Runs one scenario to its end. A scenario that cannot run (start in
 * collision, target inside an obstacle, non-finite poses) returns at once
 * with that outcome; nothing here loops without the timeout's bound. */
NavigationRun runNavigation(const NavigationScenario& scenario, const NavigationSetup& setup);

}  // namespace lvf::navigation
