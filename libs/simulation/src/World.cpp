#include <lvfusion/simulation/World.h>

#include <algorithm>
#include <cmath>

namespace lvf::simulation
{
void World::footprintBounds(
	double& xMin, double& xMax, double& yMin, double& yMax, double margin) const
{
	xMin = yMin = 1e30;
	xMax = yMax = -1e30;
	auto include = [&](double x, double y) {
		xMin = std::min(xMin, x);
		xMax = std::max(xMax, x);
		yMin = std::min(yMin, y);
		yMax = std::max(yMax, y);
	};
	for (const auto& b : boxes)
	{
		const double r = 0.5 * std::hypot(b.sizeX, b.sizeY);
		include(b.x - r, b.y - r);
		include(b.x + r, b.y + r);
	}
	for (const auto& p : path) include(p.x, p.y);
	if (xMin > xMax) xMin = xMax = yMin = yMax = 0;
	xMin -= margin;
	yMin -= margin;
	xMax += margin;
	yMax += margin;
}

}  // namespace lvf::simulation
