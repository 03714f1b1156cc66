#pragma once
// The closed loop's own settings: section [NavigationLoop] of the navigation
// INI (the other sections are MRPT's reactive navigator's; see
// share/lvfusion/config/navigate.ini).

#include <mrpt/config/CLoadableOptions.h>

namespace lvf::navigation
{
struct NavigationLoopOptions : public mrpt::config::CLoadableOptions
{
	double controlPeriod = 0.1;	 //!< one navigation step and robot motion [s]
	int sensingEvery = 2;  //!< a sensing + grid update every this many steps
	double timeout = 120;  //!< simulated time before giving up [s]
	double targetTolerance = 0.30;	//!< reached when this close [m]
	double gridResolution = 0.05;  //!< local occupancy grid cell [m]
	double obstacleRange = 4.0;	 //!< grid cells this near go to the navigator [m]
	/** A grid cell is an obstacle when its free probability is below this
	 * (one laser hit takes a fresh cell to 0.35 with MRPT's defaults). */
	double occupiedBelow = 0.45;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& target, const std::string& section) const override;
};

}  // namespace lvf::navigation
