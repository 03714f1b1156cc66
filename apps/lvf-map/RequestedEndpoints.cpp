#include "RequestedEndpoints.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <mrpt/system/string_utils.h>

#include <cmath>
#include <stdexcept>

namespace lvf::apps
{
using lvf::common::InputError;
using mrpt::math::TPoint2D;

namespace
{
TPoint2D parsePoint(const std::string& text, const std::string& option)
{
	const auto comma = text.find(',');
	const auto number = [&](const std::string& part) {
		size_t used = 0;
		const double v = std::stod(part, &used);
		if (mrpt::system::trim(part.substr(used)) != "" || !std::isfinite(v)) throw std::invalid_argument(part);
		return v;
	};
	try
	{
		if (comma != std::string::npos) return {number(text.substr(0, comma)), number(text.substr(comma + 1))};
	}
	catch (const std::exception&)
	{
	}
	throw InputError(option, "", "expected x,y in metres, got '" + text + "'");
}
}  // namespace

RequestedEndpoints requestedEndpoints(const std::string& worldFile, const std::string& start, const std::string& goal)
{
	RequestedEndpoints r;
	if (!worldFile.empty())
	{
		const auto world = lvf::simulation::loadWorldFile(worldFile);
		r.worldStart = mrpt::poses::CPose2D(world.path.front());
		r.start = TPoint2D(world.path.front().x, world.path.front().y);
		r.startSource = r.goalSource = worldFile;
		if (!world.target) throw InputError(worldFile, "target", "the world has no target to plan to");
		r.goal = *world.target;
		r.startFromWorld = r.goalFromWorld = true;
	}
	if (!start.empty()) r.start = parsePoint(start, "--start"), r.startSource = "--start", r.startFromWorld = false;
	if (!goal.empty()) r.goal = parsePoint(goal, "--goal"), r.goalSource = "--goal", r.goalFromWorld = false;
	return r;
}

void placeWorldEndpointsOnMap(RequestedEndpoints& r, const mrpt::poses::CPose2D& mapInWorld)
{
	const auto worldToMap = -mapInWorld;
	if (r.startFromWorld) r.start = worldToMap + *r.start;
	if (r.goalFromWorld) r.goal = worldToMap + *r.goal;
}

}  // namespace lvf::apps
