#include <lvfusion/model/PlanarSceneModel.h>

#include <cmath>

namespace lvf::model
{
PlanarSceneModel::PlanarSceneModel(
	std::vector<VerticalWall> walls, double floorHeight)
	: m_walls(std::move(walls)), m_floorHeight(floorHeight)
{
}

ModelHit PlanarSceneModel::castRay(
	const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) const
{
	ModelHit best;
	if (dir.z() < 0 && origin.z() > m_floorHeight)
	{
		best.t = (m_floorHeight - origin.z()) / dir.z();
		best.surface = ModelHit::kFloor;
	}
	// A wall is unbounded in z, so only the horizontal projection matters:
	// solve origin.xy + t dir.xy = start + s (end - start), s in [0, 1].
	const Eigen::Vector2d o = origin.head<2>(), d = dir.head<2>();
	for (size_t i = 0; i < m_walls.size(); i++)
	{
		const Eigen::Vector2d e = m_walls[i].end - m_walls[i].start;
		const double denom = d.x() * e.y() - d.y() * e.x();  // cross(d, e)
		if (std::abs(denom) < 1e-12) continue;	// parallel to the wall
		const Eigen::Vector2d w = m_walls[i].start - o;
		const double t = (w.x() * e.y() - w.y() * e.x()) / denom;
		const double s = (w.x() * d.y() - w.y() * d.x()) / denom;
		if (t > 0 && t < best.t && s >= 0 && s <= 1)
		{
			best.t = t;
			best.surface = static_cast<int>(i);
		}
	}
	return best;
}

}  // namespace lvf::model
