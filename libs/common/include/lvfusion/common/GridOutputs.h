#pragma once
// The occupancy grids the apps write: as MRPT files (.gridmap.gz, what
// MRPT's tools and lvf-map read back), and as pictures for a person to
// compare (lvf-fuse's NAME_grids.png, lvf-map's NAME_paths.png): side by
// side over one and the same area, cropped to what was observed, enlarged
// and labelled.

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace lvf::common
{
/** Writes `grid` as a gzip-compressed MRPT archive (.gridmap.gz);
 * InputError naming the file if it cannot be written. */
void saveGrid(const mrpt::maps::COccupancyGridMap2D& grid, const std::string& gridmapPath);

/** Copies of `grids` resized to the extent that holds them all (unknown
 * where a grid has no cells), so that their pictures line up pixel for
 * pixel. Each grid grows with its own scans. */
std::vector<mrpt::maps::COccupancyGridMap2D> onCommonExtent(
	const std::vector<const mrpt::maps::COccupancyGridMap2D*>& grids);

/** `pictures` (of grids on a common extent, the same size; grey or BGR)
 * side by side, each under its label: cropped to what any of them shows
 * other than the unknown grey, with a margin, and enlarged — cells as
 * square blocks — until the larger side is about `targetSize` px. */
cv::Mat sideBySide(
	const std::vector<cv::Mat>& pictures, const std::vector<std::string>& labels, int targetSize = 480);

}  // namespace lvf::common
