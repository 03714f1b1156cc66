#include <lvfusion/simulation/WorldGeometry.h>

#include <cmath>

namespace lvf::simulation
{
bool intersectSlabs(
	const double* origin, const double* dir, const double* half, int n,
	double& tEnter, int& enterAxis)
{
	double tNear = -std::numeric_limits<double>::infinity();
	double tFar = std::numeric_limits<double>::infinity();
	enterAxis = 0;
	for (int a = 0; a < n; a++)
	{
		if (std::abs(dir[a]) < 1e-15)
		{
			if (std::abs(origin[a]) > half[a]) return false;
			continue;
		}
		const double inv = 1.0 / dir[a];
		double t1 = (-half[a] - origin[a]) * inv;
		double t2 = (half[a] - origin[a]) * inv;
		if (t1 > t2) std::swap(t1, t2);
		if (t1 > tNear)
		{
			tNear = t1;
			enterAxis = a;
		}
		tFar = std::min(tFar, t2);
		if (tNear > tFar) return false;
	}
	if (tNear <= 0) return false;  // behind the origin, or origin inside
	tEnter = tNear;
	return true;
}

WorldGeometry::WorldGeometry(const World& world)
	: m_world(world), m_floorTexture(world.floorTexture)
{
	m_boxes.reserve(world.boxes.size());
	for (const auto& b : world.boxes)
	{
		PreparedBox p;
		p.cx = b.x;
		p.cy = b.y;
		p.cz = b.elevation + 0.5 * b.sizeZ;
		p.cosYaw = std::cos(b.yaw);
		p.sinYaw = std::sin(b.yaw);
		p.half[0] = 0.5 * b.sizeX;
		p.half[1] = 0.5 * b.sizeY;
		p.half[2] = 0.5 * b.sizeZ;
		p.texture = SurfaceTexture(b.texture);
		p.shiftFaces = b.texture.kind == TextureSpec::Kind::Noise;
		m_boxes.push_back(p);
		m_allBoxes.push_back(static_cast<int>(m_allBoxes.size()));
	}
}

Eigen::Vector3d WorldGeometry::toBoxFrame(
	const PreparedBox& b, const Eigen::Vector3d& p) const
{
	const double dx = p.x() - b.cx, dy = p.y() - b.cy;
	return {
		b.cosYaw * dx + b.sinYaw * dy, -b.sinYaw * dx + b.cosYaw * dy,
		p.z() - b.cz};
}

void WorldGeometry::intersectBox(
	int index, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
	RayHit& best) const
{
	const PreparedBox& b = m_boxes[index];
	const Eigen::Vector3d o = toBoxFrame(b, origin);
	const double d[3] = {
		b.cosYaw * dir.x() + b.sinYaw * dir.y(),
		-b.sinYaw * dir.x() + b.cosYaw * dir.y(), dir.z()};
	double t;
	int axis;
	if (!intersectSlabs(o.data(), d, b.half, 3, t, axis) || t >= best.t)
		return;
	best.t = t;
	best.box = index;
	best.axis = axis;
	best.side = d[axis] > 0 ? -1.0 : 1.0;  // entering through the face facing the ray
}

RayHit WorldGeometry::castRay(
	const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
	const int* candidates, size_t candidateCount, double tMax) const
{
	RayHit best;
	best.t = tMax;
	if (dir.z() < 0 && origin.z() > 0)
	{
		const double t = -origin.z() / dir.z();
		if (t < best.t)
		{
			best.t = t;
			best.box = RayHit::kFloor;
			best.axis = 2;
		}
	}
	for (size_t i = 0; i < candidateCount; i++)
		intersectBox(candidates[i], origin, dir, best);
	if (!best.hit()) best.t = std::numeric_limits<double>::infinity();
	return best;
}

RayHit WorldGeometry::castRay(
	const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
	double tMax) const
{
	return castRay(origin, dir, m_allBoxes.data(), m_allBoxes.size(), tMax);
}

Eigen::Vector3d WorldGeometry::normalAt(const RayHit& hit) const
{
	if (hit.box == RayHit::kFloor) return {0, 0, 1};
	const PreparedBox& b = m_boxes[hit.box];
	switch (hit.axis)
	{
		case 0: return {hit.side * b.cosYaw, hit.side * b.sinYaw, 0};
		case 1: return {-hit.side * b.sinYaw, hit.side * b.cosYaw, 0};
		default: return {0, 0, hit.side};
	}
}

float WorldGeometry::albedoAt(
	const RayHit& hit, const Eigen::Vector3d& origin, const Eigen::Vector3d& dir,
	double footprint) const
{
	const Eigen::Vector3d p = origin + hit.t * dir;
	if (hit.box == RayHit::kFloor) return m_floorTexture.albedoAt(p.x(), p.y(), footprint);
	const PreparedBox& b = m_boxes[hit.box];
	const Eigen::Vector3d q = toBoxFrame(b, p);
	// Each face gets its own stretch of a noise texture so that opposite and
	// neighbouring faces do not repeat one another. Checkers stay aligned to
	// the face centre (a square corner there), as a calibration target is.
	const double faceShift = b.shiftFaces
		? 7.31 * (2 * hit.axis + (hit.side > 0 ? 1 : 0))
		: 0.0;
	switch (hit.axis)
	{
		case 0: return b.texture.albedoAt(q.y() + faceShift, q.z(), footprint);
		case 1: return b.texture.albedoAt(q.x() + faceShift, q.z(), footprint);
		default: return b.texture.albedoAt(q.x() + faceShift, q.y(), footprint);
	}
}

}  // namespace lvf::simulation
