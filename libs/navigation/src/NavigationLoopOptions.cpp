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
}

}  // namespace lvf::navigation
