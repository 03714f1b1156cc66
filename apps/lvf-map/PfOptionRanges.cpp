#include "PfOptionRanges.h"

#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <mrpt/core/format.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/system/string_utils.h>
#include <mrpt/typemeta/TEnumType.h>

namespace lvf::apps
{
using lvf::common::InputError;

namespace
{
// Range checks of what the user's file gives: MRPT reads the values itself,
// from the defaults with that file over them, so a key the file leaves out
// is the default's and not checked (the lower bound stands in for a value
// never used).
void realInRange(lvf::common::IniSection& ini, const std::string& key, double lowest, double highest)
{
	ini.real(key, lowest, lowest, highest);
}
void integerInRange(lvf::common::IniSection& ini, const std::string& key, int lowest, int highest)
{
	ini.integer(key, lowest, lowest, highest);
}

/** A number of the defaults with the user's file over them: always there. */
int mergedInteger(const mrpt::config::CConfigFileBase& merged, const std::string& section, const std::string& key)
{
	return merged.read_int(section, key, 0, /* failIfNotFound */ true);
}

/** The filter's algorithm choices, which MRPT refuses (as its own
 * exception) only on the run's first step. */
void requireFilterChoices(const mrpt::config::CConfigFileBase& user, const mrpt::config::CConfigFileBase& merged)
{
	lvf::common::IniSection ini(user, "PF_options");
	integerInRange(ini, "PF_algorithm", 0, 3);
	integerInRange(ini, "resamplingMethod", 0, 3);
	integerInRange(ini, "adaptiveSampleSize", 0, 1);
	realInRange(ini, "BETA", 0, 1);
	integerInRange(ini, "pfAuxFilterOptimal_MaximumSearchSamples", 1, kMostParticles);
	// MRPT's KLD-adaptive sampling draws multinomially and throws otherwise.
	if (mergedInteger(merged, "PF_options", "adaptiveSampleSize") != 0 &&
		mergedInteger(merged, "PF_options", "resamplingMethod") != 0)
		throw InputError(ini.sourceName(), "[PF_options] resamplingMethod",
			"must be 0 (multinomial) with adaptiveSampleSize = 1, MRPT's KLD sampling draws no other way");
}

void requireKldBounds(const mrpt::config::CConfigFileBase& user, const mrpt::config::CConfigFileBase& merged)
{
	lvf::common::IniSection ini(user, "KLD_options");
	realInRange(ini, "KLD_binSize_PHI_deg", 1e-3, 360);
	realInRange(ini, "KLD_binSize_XY", 1e-4, 1e3);
	realInRange(ini, "KLD_delta", 1e-9, 1 - 1e-9);  // a probability, and MRPT takes its normal quantile
	realInRange(ini, "KLD_epsilon", 1e-9, 1);
	integerInRange(ini, "KLD_maxSampleSize", 1, kMostParticles);
	integerInRange(ini, "KLD_minSampleSize", 1, kMostParticles);
	integerInRange(ini, "KLD_minSamplesPerBin", 0, kMostParticles);
	if (mergedInteger(merged, "KLD_options", "KLD_minSampleSize") > mergedInteger(merged, "KLD_options", "KLD_maxSampleSize"))
		throw InputError(ini.sourceName(), "[KLD_options] KLD_minSampleSize", "must not exceed KLD_maxSampleSize");
}

void requireOdometryFloors(const mrpt::config::CConfigFileBase& user)
{
	lvf::common::IniSection ini(user, "DummyOdometryParams");
	realInRange(ini, "minStdXY", 0, 100);
	realInRange(ini, "minStdPHI", 0, 180);
}

/** MRPT's TLikelihoodMethod by number (MRPT casts it unchecked) or by name,
 * asked of MRPT's own enum table: MRPT's loader refuses an unknown name by
 * throwing after it allocated the map's definition, which then leaks. */
void requireLikelihoodMethod(lvf::common::IniSection& likelihood)
{
	using Grid = mrpt::maps::COccupancyGridMap2D;
	using Methods = mrpt::typemeta::TEnumType<Grid::TLikelihoodMethod>;
	constexpr int first = Grid::lmMeanInformation, last = Grid::lmConsensusOWA;
	const std::string method = mrpt::system::trim(likelihood.text("likelihoodMethod", ""));
	if (method.empty()) return;
	if (method.find_first_not_of("+-0123456789") == std::string::npos)
	{
		integerInRange(likelihood, "likelihoodMethod", first, last);
		return;
	}
	try
	{
		Methods::name2value(method);
	}
	catch (const std::exception&)
	{
		std::string names;
		for (int m = first; m <= last; m++)
			names += (m == first ? "" : ", ") + Methods::value2name(static_cast<Grid::TLikelihoodMethod>(m));
		throw InputError(likelihood.sourceName(), "[" + likelihood.section() + "] likelihoodMethod",
			"'" + method + "' is not one of MRPT's likelihood methods (" + names +
				mrpt::format(", or %d-%d)", first, last));
	}
}

/** Each occupancy grid's insertion and likelihood numbers that lvf-map's
 * use depends on (the others belong to likelihood methods it does not use
 * by default and keep MRPT's reading). */
void requireGridOptions(const mrpt::config::CConfigFileBase& user, const mrpt::config::CConfigFileBase& merged)
{
	lvf::common::IniSection maps(user, "MetricMap");
	integerInRange(maps, "occupancyGrid_count", 0, 100);
	integerInRange(maps, "pointsMap_count", 0, 100);
	const int grids = mergedInteger(merged, "MetricMap", "occupancyGrid_count");
	if (grids + mergedInteger(merged, "MetricMap", "pointsMap_count") < 1)
		throw InputError(maps.sourceName(), "[MetricMap] occupancyGrid_count",
			"no occupancy grid or points map: the particle filter would have nothing to score the scans in");
	for (int k = 0; k < grids; k++)
	{
		const std::string prefix = mrpt::format("MetricMap_occupancyGrid_%02d_", k);
		lvf::common::IniSection creation(user, prefix + "creationOpts");
		realInRange(creation, "resolution", 1e-4, 100);
		lvf::common::IniSection insert(user, prefix + "insertOpts");
		realInRange(insert, "maxOccupancyUpdateCertainty", 0.5, 1);
		realInRange(insert, "maxDistanceInsertion", 0, 1e6);
		realInRange(insert, "minLaserScanNoiseStd", 0, 100);
		lvf::common::IniSection likelihood(user, prefix + "likelihoodOpts");
		requireLikelihoodMethod(likelihood);
		integerInRange(likelihood, "LF_decimation", 1, 1000000);
		realInRange(likelihood, "LF_stdHit", 1e-6, 1e3);
		realInRange(likelihood, "LF_maxCorrsDistance", 1e-6, 1e3);
		realInRange(likelihood, "LF_zHit", 0, 1);
		realInRange(likelihood, "LF_zRandom", 0, 1);
		realInRange(likelihood, "LF_maxRange", 1e-6, 1e6);
	}
}
}  // namespace

void requireUsablePfOptions(const mrpt::config::CConfigFileBase& user, const mrpt::config::CConfigFileBase& merged)
{
	requireFilterChoices(user, merged);
	requireKldBounds(user, merged);
	requireOdometryFloors(user);
	requireGridOptions(user, merged);
}

}  // namespace lvf::apps
