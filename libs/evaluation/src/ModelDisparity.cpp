#include <lvfusion/common/RowBands.h>
#include <lvfusion/common/VectorClones.h>
#include <lvfusion/evaluation/ModelDisparity.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace lvf::evaluation
{
namespace
{
/** g(u, v) = a u + b v + c over the pixels of the rectified left image. */
struct PixelAffine
{
	double a = 0, b = 0, c = 0;
};

/** `k * (n . ray(u, v))` for a camera-frame vector n, as a PixelAffine. */
PixelAffine dotWithRay(const Eigen::Vector3d& n, double k, const RectifiedGeometry& g)
{
	// ray(u, v) = ((u - cx) / f, (v - cy) / f, 1)
	return {k * n.x() / g.f, k * n.y() / g.f,
			k * (n.z() - n.x() * g.cx / g.f - n.y() * g.cy / g.f)};
}

/** Columns [lo, hi] of row v where g >= 0 (lo > hi: none). Clipping only
 * narrows [0, last column], so a non-empty result lies inside the image. */
void clipToNonNegative(const PixelAffine& g, double v, double& lo, double& hi)
{
	const double c = g.b * v + g.c;	 // g = a u + c on this row
	if (std::abs(g.a) < 1e-15)
	{
		// None. Not hi + 1: beyond 2^53 that equals hi (a far-off root of
		// an earlier clip, from a corrupt calibration: fuzz_fusion_frame).
		if (c < 0) lo = 1, hi = 0;
		return;
	}
	const double root = -c / g.a;
	if (g.a > 0) lo = std::max(lo, root);
	else hi = std::min(hi, root);
}

struct Wall
{
	PixelAffine disparity, edgeA, edgeB;
};

/** row[u] = max(0, the floor's disparity a u + bv + c) over a whole row
 * (rounded to float before the max, which is the same value and lets GCC
 * vectorise the loop). */
LVF_VECTOR_CLONES void renderFloorRow(double a, double bv, double c, int width, float* __restrict row)
{
	for (int u = 0; u < width; u++) row[u] = std::max(0.f, static_cast<float>(a * u + bv + c));
}

/** row[u] = max(row[u], a wall's disparity) over columns u0 .. u1: the
 * nearest surface wins. */
LVF_VECTOR_CLONES void renderWallRow(double a, double rowC, int u0, int u1, float* __restrict row)
{
	for (int u = u0; u <= u1; u++) row[u] = std::max(row[u], static_cast<float>(a * u + rowC));
}

}  // namespace

cv::Mat1f renderModelDisparity(
	const lvf::model::PlanarSceneModel& model, const RectifiedGeometry& g)
{
	const Eigen::Matrix3d Rc = g.leftPose.getRotationMatrix().asEigen();
	const Eigen::Vector3d C = g.cameraCentre();
	// Plane n . X = c (robot frame) -> disparity fB / Z = fB (n_c . ray) / c_c
	// with n_c = Rc^T n and c_c = c - n . C (camera frame).
	auto planeDisparity = [&](const Eigen::Vector3d& n, double c, bool& ok) {
		const double cc = c - n.dot(C);
		ok = std::abs(cc) > 1e-9;  // the camera is not inside the plane
		return dotWithRay(Rc.transpose() * n, ok ? g.fB() / cc : 0.0, g);
	};

	bool floorOk = false;
	const PixelAffine floor =
		planeDisparity({0, 0, 1}, model.floorHeight(), floorOk);

	std::vector<Wall> walls;
	for (const auto& w : model.walls())
	{
		const Eigen::Vector2d e = w.end - w.start;
		if (e.norm() < 1e-9) continue;
		bool ok = false;
		Wall wall;
		wall.disparity = planeDisparity(
			Eigen::Vector3d(-e.y(), e.x(), 0).normalized(),
			Eigen::Vector2d(-e.y(), e.x()).normalized().dot(w.start), ok);
		if (!ok) continue;
		// Vertical plane through the camera centre and one endpoint, its
		// normal oriented towards the other endpoint: rays between both
		// planes meet the wall between its endpoints.
		auto edge = [&](const Eigen::Vector2d& p, const Eigen::Vector2d& other) {
			const Eigen::Vector2d q = p - C.head<2>(), r = other - C.head<2>();
			Eigen::Vector3d m(q.y(), -q.x(), 0);
			if (m.head<2>().dot(r) < 0) m = -m;
			return dotWithRay(Rc.transpose() * m, 1.0, g);
		};
		wall.edgeA = edge(w.start, w.end);
		wall.edgeB = edge(w.end, w.start);
		walls.push_back(wall);
	}

	// Not cleared first: the floor writes every pixel of a row (0 where it
	// is not in view), so a cleared matrix would be written twice (1 % of
	// the fusion's time in lvf-bench's seeded rooms).
	cv::Mat1f disparity(g.size);
	const double lastCol = g.size.width - 1;
	// Rows are independent: on OpenCV's threads (RowBands.h).
	lvf::common::forEachRow(g.size.height, [&](int v) {
		float* row = disparity.ptr<float>(v);
		if (floorOk) renderFloorRow(floor.a, floor.b * v, floor.c, g.size.width, row);
		else std::fill(row, row + g.size.width, 0.f);
		for (const Wall& w : walls)
		{
			double lo = 0, hi = lastCol;
			clipToNonNegative(w.edgeA, v, lo, hi);
			clipToNonNegative(w.edgeB, v, lo, hi);
			clipToNonNegative(w.disparity, v, lo, hi);	// in front of the camera
			if (lo > hi) continue;
			const int u0 = static_cast<int>(std::ceil(lo)), u1 = static_cast<int>(std::floor(hi));
			renderWallRow(w.disparity.a, w.disparity.b * v + w.disparity.c, u0, u1, row);
		}
	});
	return disparity;
}

}  // namespace lvf::evaluation
