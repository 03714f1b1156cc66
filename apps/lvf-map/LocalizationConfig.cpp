#include "LocalizationConfig.h"
#include "PfOptionRanges.h"

#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/LikelyMeant.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/math/wrap2pi.h>
#include <mrpt/system/filesystem.h>

#include <algorithm>
#include <set>
#include <filesystem>

namespace lvf::apps
{
namespace fs = std::filesystem;
using lvf::common::InputError;
using lvf::common::writeOption;

namespace
{
const char* kPlannerSection = "ValueIterationPlanner";
const char* kGlobalMapsSection = "GlobalMaps";
const char* kExperiment = "LocalizationExperiment";

// The defaults of the pf-localization sections, in MRPT's own format and
// with MRPT's key names (see MRPT's localization_demo.ini). Tuned for a
// tracked (not global) localisation on a 5 cm grid with a 10 m laser.
const char* kDefaultPfSections = R"ini([KLD_options]
KLD_binSize_PHI_deg = 2             // KLD histogram bin, heading [deg]
KLD_binSize_XY = 0.02               // KLD histogram bin, position [m]
KLD_delta = 0.01                    // KLD bound: probability of exceeding epsilon [0..1]
KLD_epsilon = 0.01                  // KLD bound on the sampling error [0..1]
KLD_maxSampleSize = 5000            // most particles [count]
KLD_minSampleSize = 300             // fewest particles [count]
KLD_minSamplesPerBin = 0            // particles at least per occupied bin [count]

[PF_options]
PF_algorithm = 0                    // 0 standard proposal, 1 auxiliary PF, 2 optimal, 3 auxiliary optimal
resamplingMethod = 0                // 0 multinomial, 1 residual, 2 stratified, 3 systematic
adaptiveSampleSize = 1              // 1: KLD-adaptive number of particles
pfAuxFilterOptimal_MaximumSearchSamples = 10  // PF_algorithm 3 only [count]
BETA = 0.5                          // resample when the effective sample size falls below this [0..1]
sampleSize = 1                      // unused here (particles_count below), as in pf-localization

[DummyOdometryParams]
# Floors wider than this odometry's errors: measured on the whole
# ../shared/data/laser/mit-csail.rawlog (a robot at up to 2 m/s) against its
# own ICP-built map, filter seeds 1-10, the filter followed the robot to the
# end in 9 runs with these, 3 of 5 with pf-localization's demo values
# (0.15 m, 2 deg), and lost it at scan ~600 in most runs with 0.02 m, 1 deg
# (share/doc/lvfusion/measurements.md).
minStdXY = 0.15                     // odometry noise floor, observation-only rawlogs [m]
minStdPHI = 5                       // odometry heading noise floor, observation-only rawlogs [deg]

[LocalizationExperiment]
; map_file: the prior map (--map overrides it); a relative one from the current folder, else from this file's folder
map_file =
particles_count = 2000              // initial particles [count]
init_PDF_mode = 1                   // 1: uniform over the box below, 0: over its free grid cells
init_PDF_min_x = -0.2               // initial box [m]
init_PDF_max_x = 0.2                // [m]
init_PDF_min_y = -0.2               // [m]
init_PDF_max_y = 0.2                // [m]
init_PDF_min_yaw_deg = -5           // [deg]
init_PDF_max_yaw_deg = 5            // [deg]

[MetricMap]
occupancyGrid_count = 1             // the prior map's occupancy grid [count]
gasGrid_count = 0
landmarksMap_count = 0
pointsMap_count = 0
beaconMap_count = 0
likelihoodMapSelection = -1         // -1: all maps score the scans
enableInsertion_pointsMap = 1
enableInsertion_landmarksMap = 1
enableInsertion_gridMaps = 1
enableInsertion_gasGridMaps = 1
enableInsertion_beaconMap = 1

[MetricMap_occupancyGrid_00_creationOpts]
resolution = 0.05                   // prior grid cell size (a .simplemap is rendered at it) [m]

[MetricMap_occupancyGrid_00_insertOpts]
mapAltitude = 0                     // [m]
useMapAltitude = 0
maxDistanceInsertion = 15           // scan points farther are not inserted [m]
maxOccupancyUpdateCertainty = 0.55  // evidence per scan [0.5..1]
considerInvalidRangesAsFreeSpace = 1
minLaserScanNoiseStd = 0.001        // [m]

[MetricMap_occupancyGrid_00_likelihoodOpts]
likelihoodMethod = 4                // 4: likelihood field (truncated); see MRPT's COccupancyGridMap2D
LF_decimation = 5                   // score every Nth ray [count]
LF_stdHit = 0.05                    // likelihood field: range noise [m]
LF_maxCorrsDistance = 0.30          // likelihood field: farthest correspondence [m]
LF_zHit = 0.95                      // weight of a hit [0..1]
LF_zRandom = 0.05                   // weight of a random reading [0..1]
LF_maxRange = 80                    // rays longer are not scored [m]
LF_alternateAverageMethod = 0
MI_exponent = 10                    // (other likelihood methods, unused with 4)
MI_skip_rays = 10
MI_ratio_max_distance = 2
rayTracing_useDistanceFilter = 0
rayTracing_decimation = 10
rayTracing_stdHit = 0.30
consensus_takeEachRange = 30
consensus_pow = 1
)ini";

/** pf-localization keys about its own windows, logs and repetitions:
 * accepted so that its .ini files work, and unused. */
const std::set<std::string> kIgnoredExperimentKeys{
	"use_3D_poses", "rawlog_file", "rawlog_offset", "logOutput_dir", "3DSceneFrequency",
	"3DSceneFollowRobot", "experimentRepetitions", "experimentTestConvergenceAtStep",
	"SHOW_PROGRESS_3D_REAL_TIME", "SHOW_PROGRESS_3D_REAL_TIME_DELAY_MS", "SAVE_STATS_ONLY",
	"DO_RELIABILITY_ESTIMATE", "DO_SCAN_LIKELIHOOD_DEBUG", "STATS_CONF_INTERVAL",
	"ground_truth_path_file", "initial_odo_x", "initial_odo_y", "initial_odo_phi",
	"init_PDF_min_z", "init_PDF_max_z", "init_PDF_min_pitch_deg", "init_PDF_max_pitch_deg",
	"init_PDF_min_roll_deg", "init_PDF_max_roll_deg"};

/** Writes the user's pf-localization keys over the defaults, rejecting
 * sections and keys the defaults do not know. */
void overlayUserKeys(const mrpt::config::CConfigFileBase& user, mrpt::config::CConfigFileMemory& merged)
{
	const std::string source = lvf::common::configSourceName(user);
	std::vector<std::string> sections, known;
	user.getAllSections(sections);
	merged.getAllSections(known);
	for (const auto& rawSection : sections)
	{
		const std::string section = mrpt::system::trim(rawSection);
		if (section.empty() || section == kPlannerSection || section == kGlobalMapsSection) continue;
		if (std::find(known.begin(), known.end(), section) == known.end())
			throw InputError(source, "[" + section + "]", "unknown section" + lvf::common::didYouMean(section, known));
		const auto defaults = lvf::common::keyNames(merged, section);
		for (const auto& key : lvf::common::keyNames(user, section))
		{
			const bool ignored = section == kExperiment && kIgnoredExperimentKeys.count(key);
			if (!ignored && std::find(defaults.begin(), defaults.end(), key) == defaults.end())
				throw InputError(
					source, "[" + section + "] " + key, "unknown key" + lvf::common::didYouMean(key, defaults));
			// Only changed values are rewritten: the others keep their comments.
			const std::string value = user.read_string(section, key, "");
			if (value != merged.read_string(section, key, "")) merged.write(section, key, value);
		}
	}
}
}  // namespace

void GlobalMapsOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	resolution = ini.real("resolution", resolution, 0.005, 5);
	ownMapInitXY = ini.real("own_map_init_xy", ownMapInitXY, 0, 100);
	ownMapInitYawDeg = ini.real("own_map_init_yaw_deg", ownMapInitYawDeg, 0, 180);
	imageResolution = ini.real("image_resolution", imageResolution, 0.001, 10);
	visualMinHits = ini.integer("visual_min_hits", visualMinHits, 1, 1000000);
	ini.rejectUnknownKeys();
}

void GlobalMapsOptions::saveToConfigFile(mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "resolution", resolution, "cell size of the laser-only and fused global grids [m]");
	writeOption(c, s, "own_map_init_xy", ownMapInitXY, "no prior map: particles start within this of the first odometry pose [m]");
	writeOption(c, s, "own_map_init_yaw_deg", ownMapInitYawDeg, "no prior map: ...and within this of its heading [deg]");
	writeOption(c, s, "image_resolution", imageResolution, "cell size of a prior map given as an image [m/pixel]");
	writeOption(c, s, "visual_min_hits", visualMinHits, "a fused-map cell where vision ended this many bearings stays occupied [count]");
}

LocalizationConfig LocalizationConfig::load(const std::string& path)
{
	LocalizationConfig c;
	if (!path.empty()) c.source = path;
	const std::string& source = c.source;
	c.pfSections.setContent(std::string(kDefaultPfSections));
	std::unique_ptr<mrpt::config::CConfigFile> user;
	if (!path.empty())
	{
		user = lvf::common::openIniFile(path);
		overlayUserKeys(*user, c.pfSections);
		c.globalMaps.loadFromConfigFile(*user, kGlobalMapsSection);
		c.planner.loadFromConfigFile(*user, kPlannerSection);
	}
	// Strict numbers where MRPT's reader would take "abc" as 0: the defaults,
	// then the user's file (naming it in errors) over them.
	c.readExperiment(mrpt::config::CConfigFileMemory(std::string(kDefaultPfSections)));
	if (user) c.readExperiment(*user);
	// A relative map_file: from the current folder, as pf-localization takes
	// it, else from the .ini's folder (where a missing one is then named).
	if (!c.mapFile.empty() && user && !mrpt::system::fileExists(c.mapFile) && fs::path(c.mapFile).is_relative())
		c.mapFile = (fs::path(path).parent_path() / c.mapFile).lexically_normal().string();
	if (user) requireUsablePfOptions(*user, c.pfSections);
	if (c.initMin.x > c.initMax.x || c.initMin.y > c.initMax.y || c.initMin.phi > c.initMax.phi)
		throw InputError(source, "[LocalizationExperiment] init_PDF_min_*",
						 "must not exceed init_PDF_max_*");
	const auto& cfg = c.pfSections;
	try
	{
		c.pf.loadFromConfigFile(cfg, "PF_options");
		c.monteCarlo.KLD_params.loadFromConfigFile(cfg, "KLD_options");
		c.maps.loadFromConfigFile(cfg, "MetricMap");
		// MRPT checks a map's options (a cell size > 0, ...) only as it
		// builds the map, deep in a run: built once here to ask.
		mrpt::maps::CMultiMetricMap maps(c.maps);
	}
	catch (const std::exception& e)
	{
		throw InputError(source, "", "MRPT's particle filter or maps refuse it: " + lvf::common::exceptionMessage(e));
	}
	c.obsOnlyOdometry.modelSelection = mrpt::obs::CActionRobotMovement2D::mmGaussian;
	// (The defaults give both keys: nothing to fall back on.)
	c.obsOnlyOdometry.gaussianModel.minStdXY = cfg.read_double("DummyOdometryParams", "minStdXY", 0, true);
	c.obsOnlyOdometry.gaussianModel.minStdPHI = mrpt::DEG2RAD(cfg.read_double("DummyOdometryParams", "minStdPHI", 0, true));
	return c;
}

void LocalizationConfig::readExperiment(const mrpt::config::CConfigFileBase& cfg)
{
	lvf::common::IniSection ini(cfg, kExperiment);
	// A file that gives any of the initial box gives all of it, with
	// pf-localization's defaults (0 m, +-180 deg) for what it leaves out.
	const auto keys = lvf::common::keyNames(cfg, kExperiment);
	// (init_PDF_mode, the box's use, is no part of it.)
	const auto isBoxKey = [](const std::string& k) {
		return k.rfind("init_PDF_min_", 0) == 0 || k.rfind("init_PDF_max_", 0) == 0;
	};
	if (std::any_of(keys.begin(), keys.end(), isBoxKey))
	{
		initMin = {0, 0, -M_PI};
		initMax = {0, 0, M_PI};
	}
	particles = static_cast<size_t>(ini.integer("particles_count", static_cast<int>(particles), 1, kMostParticles));
	initOnFreeSpace = ini.integer("init_PDF_mode", initOnFreeSpace ? 0 : 1, 0, 1) == 0;
	initMin = {ini.real("init_PDF_min_x", initMin.x), ini.real("init_PDF_min_y", initMin.y),
			   mrpt::DEG2RAD(ini.real("init_PDF_min_yaw_deg", mrpt::RAD2DEG(initMin.phi), -360, 360))};
	initMax = {ini.real("init_PDF_max_x", initMax.x), ini.real("init_PDF_max_y", initMax.y),
			   mrpt::DEG2RAD(ini.real("init_PDF_max_yaw_deg", mrpt::RAD2DEG(initMax.phi), -360, 360))};
	mapFile = ini.text("map_file", mapFile);
}

std::string LocalizationConfig::dump() const
{
	mrpt::config::CConfigFileMemory out(pfSections.getContent());
	globalMaps.saveToConfigFile(out, kGlobalMapsSection);
	planner.saveToConfigFile(out, kPlannerSection);
	return out.getContent();
}

}  // namespace lvf::apps
