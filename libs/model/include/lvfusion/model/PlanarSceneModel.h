#pragma once
// Stage 2 (paper §3): the 3D model one laser scan implies. An infinite
// horizontal floor plus, for every line segment of the scan, the vertical
// plane through it, bounded by the segment's endpoints and unbounded in
// height. Everything is in the robot frame (x forward, y left, z up, floor at
// z = floorHeight) at the time of the scan.

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace lvf::model
{
/** A vertical rectangle of unbounded height standing on a 2D segment. */
struct VerticalWall
{
	Eigen::Vector2d start, end;	 //!< robot frame [m]
};

struct ModelHit
{
	static constexpr int kNone = -2;
	static constexpr int kFloor = -1;
	double t = std::numeric_limits<double>::infinity();	 //!< ray parameter
	int surface = kNone;  //!< wall index, kFloor or kNone
	bool hit() const { return surface != kNone; }
};

class PlanarSceneModel
{
   public:
	PlanarSceneModel() = default;
	PlanarSceneModel(std::vector<VerticalWall> walls, double floorHeight = 0.0);

	/** Nearest surface along origin + t * dir, t > 0 (dir need not be unit). */
	ModelHit castRay(const Eigen::Vector3d& origin, const Eigen::Vector3d& dir) const;

	const std::vector<VerticalWall>& walls() const { return m_walls; }
	double floorHeight() const { return m_floorHeight; }

   private:
	std::vector<VerticalWall> m_walls;
	double m_floorHeight = 0;
};

}  // namespace lvf::model
