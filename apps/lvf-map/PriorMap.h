#pragma once
// The map the particle filter localises against, as MRPT's pf-localization
// takes it: a .simplemap(.gz) (poses + scans, rendered into the maps of
// [MetricMap]), a .gridmap(.gz) (a serialised COccupancyGridMap2D), or, as
// MRPT's grid can read it, an image (dark = occupied) centred on the origin.
// Without one, lvf-map builds it from the run's own laser scans and odometry
// with MRPT's ICP-SLAM (CMetricMapBuilderICP).

#include "MapRun.h"

#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/CSimpleMap.h>

#include <string>

namespace lvf::apps
{
/** Fills `map` from `path`; returns what was loaded, for the summary.
 * Throws InputError naming the file for an unknown format or a bad file. */
std::string loadPriorMap(const std::string& path, double imageResolution, mrpt::maps::CMultiMetricMap& map);

/** Renders a non-empty `simple` into `map`, as MRPT's
 * loadFromProbabilisticPosesAndObservations does, but with the occupancy grids
 * started round the first keyframe rather than round the origin, so that they
 * cover where the keyframes are and no more. */
void loadSimpleMap(const mrpt::maps::CSimpleMap& simple, mrpt::maps::CMultiMetricMap& map);

/** Poses and laser scans of the run after ICP-SLAM (MRPT's defaults, one
 * keyframe every 0.5 m or 10 degrees), in the odometry frame (the first
 * keyframe at the first odometry pose). */
mrpt::maps::CSimpleMap buildMapFromScans(const MapRun& run);

}  // namespace lvf::apps
