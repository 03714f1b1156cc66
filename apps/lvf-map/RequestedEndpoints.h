#pragma once
// Where lvf-map's plans start and end when the user says so: --world (its
// first path pose and its target, in the world's frame), then --start and
// --goal (in the map's frame) over it.

#include <mrpt/math/TPoint2D.h>
#include <mrpt/poses/CPose2D.h>

#include <optional>
#include <string>

namespace lvf::apps
{
/** The start and goal the user asked for (none: the run's first and last
 * localised poses), and which input named each, for error messages. */
struct RequestedEndpoints
{
	std::optional<mrpt::math::TPoint2D> start, goal;
	std::string startSource, goalSource;
	/** --world's first path pose: where its run starts, in the world's frame. */
	std::optional<mrpt::poses::CPose2D> worldStart;
	bool startFromWorld = false, goalFromWorld = false;	 //!< in the world's frame, not the map's
};

/** Throws InputError naming the world file or option when it is bad. */
RequestedEndpoints requestedEndpoints(const std::string& worldFile, const std::string& start, const std::string& goal);

/** The world's start and target moved into the map's frame, which lies at
 * `mapInWorld` in the world's (a map built from a sensory-frame log starts
 * where the robot stands, not at the world's origin). */
void placeWorldEndpointsOnMap(RequestedEndpoints& r, const mrpt::poses::CPose2D& mapInWorld);

}  // namespace lvf::apps
