#pragma once
// lvf-map's configuration: MRPT's pf-localization INI format for everything
// the particle filter needs ([PF_options], [KLD_options],
// [DummyOdometryParams], [LocalizationExperiment], [MetricMap] and its
// MetricMap_occupancyGrid_00_* sections, read by MRPT's own loaders, so a
// pf-localization .ini works as it is), plus two lvfusion sections:
// [GlobalMaps] (the accumulated grids) and [ValueIterationPlanner].
//
// MRPT's loaders ignore unknown keys and read "abc" as 0; here every key of a
// pf-localization section must be one the built-in defaults list (or one of
// pf-localization's display/logging keys, accepted and unused), the
// numbers of [LocalizationExperiment] and the filter's algorithm choices are
// parsed strictly, and the maps [MetricMap] describes are built once to see
// that MRPT can (it asserts on their options only as it builds them).

#include <lvfusion/planning/ValueIterationPlanner.h>
#include <mrpt/bayes/CParticleFilter.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/slam/TMonteCarloLocalizationParams.h>

#include <string>

namespace lvf::apps
{
/** [GlobalMaps]: the grids the scans are accumulated into. */
struct GlobalMapsOptions : public mrpt::config::CLoadableOptions
{
	double resolution = 0.05;  //!< cell size [m]
	/** With no prior map, the particles start this close to the first
	 * odometry pose (the map built from the run is in the odometry frame). */
	double ownMapInitXY = 0.2;	//!< [m], half-width
	double ownMapInitYawDeg = 5;  //!< [deg], half-width
	double imageResolution = 0.05;	//!< cell size of a prior map given as an image [m/pixel]
	/** A fused-map cell where vision ended this many bearings stays occupied
	 * (GlobalGrids.h). */
	int visualMinHits = 2;

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void saveToConfigFile(mrpt::config::CConfigFileBase& target, const std::string& section) const override;
};

struct LocalizationConfig
{
	/** The pf-localization sections: built-in defaults with the user's keys
	 * written over them. */
	mrpt::config::CConfigFileMemory pfSections;
	mrpt::bayes::CParticleFilter::TParticleFilterOptions pf;
	mrpt::slam::TMonteCarloLocalizationParams monteCarlo;  //!< KLD options
	mrpt::maps::TSetOfMetricMapInitializers maps;
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions obsOnlyOdometry;
	size_t particles = 0;
	bool initOnFreeSpace = true;  //!< init_PDF_mode = 0
	mrpt::math::TPose2D initMin, initMax;
	std::string mapFile;  //!< map_file; a relative one from the current folder, else resolved against the .ini's folder
	GlobalMapsOptions globalMaps;
	lvf::planning::ValueIterationPlanner::TOptions planner;
	std::string source = "<defaults>";  //!< the file read, as errors found later name it

	/** Defaults, with `path` (if not empty) over them; throws InputError
	 * naming the file, section and key of anything wrong. */
	static LocalizationConfig load(const std::string& path);
	/** [LocalizationExperiment]'s numbers, keeping current values as defaults. */
	void readExperiment(const mrpt::config::CConfigFileBase& cfg);
	/** The complete configuration in INI form (--dump-config). */
	std::string dump() const;
};

}  // namespace lvf::apps
