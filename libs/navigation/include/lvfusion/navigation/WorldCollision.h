#pragma once
// Collisions of the robot with the full 3D world, whatever its sensors saw:
// the robot is a vertical cylinder of radius r from the floor up to its
// height h, and every box of the world (walls, boxes, table tops, shelves)
// that has a part between the floor and h can be hit. A table top at 0.7 m
// therefore hits a 1.2 m tall robot although a laser at 0.3 m never sees it.
//
// Hand-written: MRPT's collision tools are 2D (robot shape vs points) and
// know nothing of the heights of the world's solids.

#include <lvfusion/simulation/World.h>
#include <mrpt/math/TPoint2D.h>

#include <string>
#include <vector>

namespace lvf::navigation
{
struct Clearance
{
	/** Horizontal gap between the robot's cylinder and the nearest solid it
	 * could hit [m]; negative: they overlap (0 when the robot's centre is
	 * inside a footprint, minus the radius). +inf with nothing to hit. */
	double distance;
	int box = -1;  //!< index into World::boxes of that solid, -1: none
};

class WorldCollision
{
   public:
	WorldCollision(const lvf::simulation::World& world, const lvf::simulation::RobotBody& robot);

	/** Clearance of the robot standing with its centre at `p`. */
	Clearance clearance(const mrpt::math::TPoint2D& p) const;
	bool collides(const mrpt::math::TPoint2D& p) const { return clearance(p).distance < 0; }
	/** Name of box `i` (for messages). */
	const std::string& boxName(int i) const { return m_world.boxes.at(size_t(i)).name; }

	/** Distance from `p` to the footprint rectangle of `b` (0 inside). */
	static double footprintDistance(const lvf::simulation::Box& b, const mrpt::math::TPoint2D& p);

   private:
	const lvf::simulation::World& m_world;
	lvf::simulation::RobotBody m_robot;
	std::vector<int> m_solids;	// boxes between the floor and the robot's top
};

}  // namespace lvf::navigation
