#include "PriorMap.h"

#include "GlobalGrids.h"
#include "SerialisedFile.h"

#include <lvfusion/common/CountedNoun.h>
#include <lvfusion/common/GridInsertion.h>
#include <lvfusion/common/InputError.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/slam/CMetricMapBuilderICP.h>
#include <mrpt/system/filesystem.h>
#include <mrpt/system/string_utils.h>

#include <set>

namespace lvf::apps
{
using lvf::common::InputError;

namespace
{
mrpt::maps::COccupancyGridMap2D& gridOf(mrpt::maps::CMultiMetricMap& map, const std::string& path)
{
	auto grid = map.mapByClass<mrpt::maps::COccupancyGridMap2D>();
	if (!grid)
		throw InputError(path, "", "[MetricMap] of the configuration has no occupancy grid to load this map into");
	return *grid;
}

}  // namespace

std::string loadPriorMap(const std::string& path, double imageResolution, mrpt::maps::CMultiMetricMap& map)
{
	lvf::common::requireRegularInputFile(path, "map file");
	// Like pf-localization: the extension decides, a trailing .gz ignored.
	const std::string ext = mrpt::system::lowerCase(mrpt::system::extractFileExtension(path, true));
	static const std::set<std::string> images{"png", "jpg", "jpeg", "bmp", "pgm", "ppm", "tif", "tiff"};
	if (ext == "simplemap")
	{
		mrpt::maps::CSimpleMap simple;
		readSerialisedFile(path, simple, "map file");
		if (simple.empty()) throw InputError(path, "", "empty simple map");
		loadSimpleMap(simple, map);
		return path + " (simple map, " + lvf::common::counted(simple.size(), "keyframe") + ")";
	}
	auto& grid = gridOf(map, path);
	if (ext == "gridmap")
	{
		readSerialisedFile(path, grid, "map file");
		return mrpt::format("%s (grid map, %ux%u cells of %.3f m)", path.c_str(), grid.getSizeX(), grid.getSizeY(), grid.getResolution());
	}
	if (images.count(ext))
	{
		if (!grid.loadFromBitmapFile(path, static_cast<float>(imageResolution)))
			throw InputError(path, "", "not a readable image");
		return mrpt::format("%s (image, %.3f m per pixel, centred on the origin)", path.c_str(), imageResolution);
	}
	throw InputError(
		path, "", (ext.empty() ? std::string("no file extension to tell the map format") : "unknown map format '." + ext + "'") +
			": expected .gridmap(.gz), .simplemap(.gz) or an image (.png, .jpg, .bmp, .pgm)");
}

void loadSimpleMap(const mrpt::maps::CSimpleMap& simple, mrpt::maps::CMultiMetricMap& map)
{
	// MRPT's loadFromProbabilisticPosesAndObservations clears the map first,
	// which puts its grids round the origin (mit-csail's prior map: 12160 x
	// 1600 cells for a building 70 m across); these start round the first
	// keyframe (startGridAround). MRPT writes and reads no keyframe without
	// its pose and observations.
	map.clear();
	const mrpt::poses::CPose3D first = simple.getAsPair(0).pose->getMeanVal();
	for (size_t i = 0; auto grid = map.mapByClass<mrpt::maps::COccupancyGridMap2D>(i); i++)
		lvf::common::startGridAround(*grid, first.x(), first.y());
	for (const auto& keyframe : simple) keyframe.sf->insertObservationsInto(map, keyframe.pose->getMeanVal());
}

mrpt::maps::CSimpleMap buildMapFromScans(const MapRun& run)
{
	mrpt::slam::CMetricMapBuilderICP icp;
	icp.ICP_options.matchAgainstTheGrid = false;
	icp.ICP_options.insertionLinDistance = 0.5;
	icp.ICP_options.insertionAngDistance = mrpt::DEG2RAD(10.0);
	mrpt::maps::TMetricMapInitializer::Ptr points(mrpt::maps::CSimplePointsMap::MapDefinition());
	icp.ICP_options.mapInitializers.clear();
	icp.ICP_options.mapInitializers.push_back(points);
	icp.setVerbosityLevel(mrpt::system::LVL_ERROR);
	icp.initialize();
	for (const auto& step : run.steps) icp.processActionObservation(*step.action, *step.laserFrame);
	mrpt::maps::CSimpleMap out;
	icp.getCurrentlyBuiltMap(out);
	// ICP-SLAM starts at the origin; move its keyframes to where odometry
	// starts, so that the map is in the odometry frame.
	const mrpt::poses::CPose3D origin(run.steps.front().odometry);
	for (size_t i = 0; i < out.size(); i++) out.getAsPair(i).pose->changeCoordinatesReference(origin);
	return out;
}

}  // namespace lvf::apps
