#pragma once
// Ray casting against a World: the floor plane z = 0 and its boxes.
// Shared by the camera renderer, the laser and the ground truth so that all
// sensors see exactly the same geometry.

#include <lvfusion/simulation/SurfaceTexture.h>
#include <lvfusion/simulation/World.h>

#include <Eigen/Core>
#include <limits>
#include <vector>

namespace lvf::simulation
{
/** Ray/slab intersection in a box's own frame (the "slab method").
 * @param origin,dir ray in the box frame; @param half half extents;
 * @param n number of axes used (2: footprint, 3: solid box).
 * On a hit from outside returns true with the entry distance and the axis of
 * the entry face; a ray starting inside reports no hit. */
bool intersectSlabs(
	const double* origin, const double* dir, const double* half, int n,
	double& tEnter, int& enterAxis);

struct RayHit
{
	static constexpr int kNone = -2;
	static constexpr int kFloor = -1;
	double t = std::numeric_limits<double>::infinity();	 //!< ray parameter
	int box = kNone;  //!< index into World::boxes, or kFloor / kNone
	int axis = 0;  //!< box face: the local axis of its normal (0, 1, 2)
	double side = 1;  //!< +1 / -1: which of the two faces on that axis
	bool hit() const { return box != kNone; }
};

class WorldGeometry
{
   public:
	explicit WorldGeometry(const World& world);

	/** Nearest hit of origin + t * dir for t in (0, tMax]; `dir` need not be
	 * unit length (t is then in units of |dir|). Tests every box. */
	RayHit castRay(
		const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
		double tMax = std::numeric_limits<double>::infinity()) const;

	/** As castRay but only against the listed boxes (and the floor). */
	RayHit castRay(
		const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
		const int* candidates, size_t candidateCount,
		double tMax = std::numeric_limits<double>::infinity()) const;

	/** Outward surface normal at a hit (world frame, unit). */
	Eigen::Vector3d normalAt(const RayHit& hit) const;
	/** Reflectance at the hit point origin + hit.t * dir, averaged over a
	 * footprint of that many metres (the size of the pixel seeing it). */
	float albedoAt(
		const RayHit& hit, const Eigen::Vector3d& origin,
		const Eigen::Vector3d& dir, double footprint = 0) const;

	const World& world() const { return m_world; }
	size_t boxCount() const { return m_boxes.size(); }

   private:
	struct PreparedBox
	{
		double cx, cy, cz, cosYaw, sinYaw;
		double half[3];
		SurfaceTexture texture;
		bool shiftFaces;
	};
	void intersectBox(
		int index, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
		RayHit& best) const;
	Eigen::Vector3d toBoxFrame(const PreparedBox& b, const Eigen::Vector3d& p) const;

	const World& m_world;
	std::vector<PreparedBox> m_boxes;
	std::vector<int> m_allBoxes;  // 0..n-1, the candidate list "every box"
	SurfaceTexture m_floorTexture;
};

}  // namespace lvf::simulation
