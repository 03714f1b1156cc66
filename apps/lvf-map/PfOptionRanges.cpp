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
constexpr int kMostParticles = 10000000;

/** The filter's algorithm choices, which MRPT refuses (as its own
 * exception) only on the run's first step. */
void requireFilterChoices(const mrpt::config::CConfigFileBase& user, const mrpt::config::CConfigFileBase& merged)
{
	lvf::common::IniSection ini(user, "PF_options");
	ini.integer("PF_algorithm", 0, 0, 3);
	ini.integer("resamplingMethod", 0, 0, 3);
	ini.integer("adaptiveSampleSize", 1, 0, 1);
	ini.real("BETA", 0.5, 0, 1);
	ini.integer("pfAuxFilterOptimal_MaximumSearchSamples", 10, 1, kMostParticles);
	// MRPT's KLD-adaptive sampling draws multinomially and throws otherwise.
	if (merged.read_int("PF_options", "adaptiveSampleSize", 1) != 0 &&
		merged.read_int("PF_options", "resamplingMethod", 0) != 0)
		throw InputError(ini.sourceName(), "[PF_options] resamplingMethod",
			"must be 0 (multinomial) with adaptiveSampleSize = 1, MRPT's KLD sampling draws no other way");
}

void requireKldBounds(const mrpt::config::CConfigFileBase& user, const mrpt::config::CConfigFileBase& merged)
{
	lvf::common::IniSection ini(user, "KLD_options");
	ini.real("KLD_binSize_PHI_deg", 2, 1e-3, 360);
	ini.real("KLD_binSize_XY", 0.02, 1e-4, 1e3);
	ini.real("KLD_delta", 0.01, 1e-9, 1 - 1e-9);  // a probability, and MRPT takes its normal quantile
	ini.real("KLD_epsilon", 0.01, 1e-9, 1);
	ini.integer("KLD_maxSampleSize", 5000, 1, kMostParticles);
	ini.integer("KLD_minSampleSize", 300, 1, kMostParticles);
	ini.integer("KLD_minSamplesPerBin", 0, 0, kMostParticles);
	if (merged.read_int("KLD_options", "KLD_minSampleSize", 300) > merged.read_int("KLD_options", "KLD_maxSampleSize", 5000))
		throw InputError(ini.sourceName(), "[KLD_options] KLD_minSampleSize", "must not exceed KLD_maxSampleSize");
}

void requireOdometryFloors(const mrpt::config::CConfigFileBase& user)
{
	lvf::common::IniSection ini(user, "DummyOdometryParams");
	ini.real("minStdXY", 0.15, 0, 100);
	ini.real("minStdPHI", 5, 0, 180);
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
		likelihood.integer("likelihoodMethod", Grid::lmLikelihoodField_Thrun, first, last);
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
	maps.integer("occupancyGrid_count", 1, 0, 100);
	maps.integer("pointsMap_count", 0, 0, 100);
	const int grids = merged.read_int("MetricMap", "occupancyGrid_count", 1);
	if (grids + merged.read_int("MetricMap", "pointsMap_count", 0) < 1)
		throw InputError(maps.sourceName(), "[MetricMap] occupancyGrid_count",
			"no occupancy grid or points map: the particle filter would have nothing to score the scans in");
	for (int k = 0; k < grids; k++)
	{
		const std::string prefix = mrpt::format("MetricMap_occupancyGrid_%02d_", k);
		lvf::common::IniSection creation(user, prefix + "creationOpts");
		creation.real("resolution", 0.05, 1e-4, 100);
		lvf::common::IniSection insert(user, prefix + "insertOpts");
		insert.real("maxOccupancyUpdateCertainty", 0.55, 0.5, 1);
		insert.real("maxDistanceInsertion", 15, 0, 1e6);
		insert.real("minLaserScanNoiseStd", 0.001, 0, 100);
		lvf::common::IniSection likelihood(user, prefix + "likelihoodOpts");
		requireLikelihoodMethod(likelihood);
		likelihood.integer("LF_decimation", 5, 1, 1000000);
		likelihood.real("LF_stdHit", 0.05, 1e-6, 1e3);
		likelihood.real("LF_maxCorrsDistance", 0.3, 1e-6, 1e3);
		likelihood.real("LF_zHit", 0.95, 0, 1);
		likelihood.real("LF_zRandom", 0.05, 0, 1);
		likelihood.real("LF_maxRange", 80, 1e-6, 1e6);
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
