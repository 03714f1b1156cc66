#include <lvfusion/simulation/World.h>

#include <algorithm>
#include <cmath>

namespace lvf::simulation
{
Box wallBetween(
	const std::string& name, const mrpt::math::TPoint2D& from, const mrpt::math::TPoint2D& to, double thickness,
	double height)
{
	Box b;
	b.name = name;
	b.x = 0.5 * (from.x + to.x);
	b.y = 0.5 * (from.y + to.y);
	b.sizeX = std::hypot(to.x - from.x, to.y - from.y);
	b.sizeY = thickness;
	b.sizeZ = height;
	b.yaw = std::atan2(to.y - from.y, to.x - from.x);
	return b;
}

std::vector<Box> tableBoxes(Box top, double height, double thickness, double legWidth)
{
	const std::string name = top.name;
	top.name = name + "/top";
	top.sizeZ = thickness;
	top.elevation = height - thickness;
	std::vector<Box> boxes{top};
	const double c = std::cos(top.yaw), s = std::sin(top.yaw);
	for (int k = 0; k < 4; k++)
	{
		const double lx = ((k & 1) ? 0.5 : -0.5) * (top.sizeX - legWidth);
		const double ly = ((k & 2) ? 0.5 : -0.5) * (top.sizeY - legWidth);
		Box leg = top;
		leg.name = name + "/leg" + std::to_string(k);
		leg.x = top.x + c * lx - s * ly;
		leg.y = top.y + s * lx + c * ly;
		leg.sizeX = leg.sizeY = legWidth;
		leg.sizeZ = height - thickness;
		leg.elevation = 0;
		boxes.push_back(leg);
	}
	return boxes;
}

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
