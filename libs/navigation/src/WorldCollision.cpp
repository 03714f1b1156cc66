#include <lvfusion/navigation/WorldCollision.h>

#include <cmath>
#include <limits>

namespace lvf::navigation
{
WorldCollision::WorldCollision(
	const lvf::simulation::World& world, const lvf::simulation::RobotBody& robot)
	: m_world(world), m_robot(robot)
{
	// The whole body counts (from the floor up), not only the band the
	// obstacle detection looks at: touching a 2 cm ledge is still a touch.
	for (size_t i = 0; i < world.boxes.size(); i++)
		if (world.boxes[i].overlapsHeights(0.0, robot.height)) m_solids.push_back(int(i));
}

double WorldCollision::footprintDistance(
	const lvf::simulation::Box& b, const mrpt::math::TPoint2D& p)
{
	// Into the box's own frame, where its footprint is axis-aligned.
	const double dx = p.x - b.x, dy = p.y - b.y;
	const double c = std::cos(b.yaw), s = std::sin(b.yaw);
	const double lx = c * dx + s * dy, ly = -s * dx + c * dy;
	const double ox = std::max(0.0, std::abs(lx) - 0.5 * b.sizeX);
	const double oy = std::max(0.0, std::abs(ly) - 0.5 * b.sizeY);
	return std::hypot(ox, oy);
}

Clearance WorldCollision::clearance(const mrpt::math::TPoint2D& p) const
{
	Clearance best{std::numeric_limits<double>::infinity(), -1};
	for (const int i : m_solids)
	{
		const double d = footprintDistance(m_world.boxes[size_t(i)], p) - m_robot.radius;
		if (d < best.distance) best = {d, i};
	}
	return best;
}

}  // namespace lvf::navigation
