#pragma once
// Reads a world file (YAML, share/lvfusion/worlds/*.yaml; the format is
// documented in share/lvfusion/worlds/README.md). Every key is checked: an
// unknown key, a wrong type, a negative size or an unreadable file is an
// InputError naming the file, the line and the element ("boxes[2].size").

#include <lvfusion/simulation/World.h>

#include <string>

namespace lvf::simulation
{
World loadWorldFile(const std::string& path);
/** Same, from text; `sourceName` is used in error messages. */
World parseWorld(const std::string& yamlText, const std::string& sourceName);

/** Poses every `step` metres along a polyline, heading along each segment;
 * the last waypoint is always included. */
std::vector<mrpt::math::TPose2D> samplePolyline(
	const std::vector<mrpt::math::TPoint2D>& waypoints, double step);

}  // namespace lvf::simulation
