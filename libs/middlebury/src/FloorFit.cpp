#include <lvfusion/middlebury/FloorFit.h>

#include <lvfusion/common/InputError.h>
#include <lvfusion/common/Medians.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/core/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace lvf::middlebury
{
namespace
{
using Points = std::vector<Eigen::Vector3d>;

/** Orients `n` towards the camera's up side (camera y points down). */
Eigen::Vector3d upwards(const Eigen::Vector3d& n) { return n.y() > 0 ? Eigen::Vector3d(-n) : n; }

size_t countInliers(const Points& pts, const FloorPlane& plane, double band)
{
	return static_cast<size_t>(std::count_if(pts.begin(), pts.end(), [&](const Eigen::Vector3d& p) {
		return std::abs(plane.height(p)) <= band;
	}));
}

/** Total least squares: the plane through the centroid whose normal is the
 * covariance's smallest eigenvector. */
FloorPlane refit(const Points& pts, const FloorPlane& plane, double band)
{
	Eigen::Vector3d mean = Eigen::Vector3d::Zero();
	size_t n = 0;
	for (const auto& p : pts)
		if (std::abs(plane.height(p)) <= band) mean += p, n++;
	if (n < 3) return plane;
	mean /= static_cast<double>(n);
	Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
	for (const auto& p : pts)
		if (std::abs(plane.height(p)) <= band) cov += (p - mean) * (p - mean).transpose();
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
	FloorPlane out = plane;
	out.normal = upwards(eig.eigenvectors().col(0));  // eigenvalues ascend
	out.offset = -out.normal.dot(mean);
	return out;
}
}  // namespace

FloorPlane fitFloor(const MiddleburyScene& scene, const FloorFitOptions& o)
{
	Points pts;
	for (const auto& g : scene.points)
		if (g.v > scene.calib.cy) pts.push_back(g.camera);
	Points scoring;
	const size_t stride = std::max<size_t>(1, pts.size() / o.maxScoringPoints);
	for (size_t i = 0; i < pts.size(); i += stride) scoring.push_back(pts[i]);

	FloorPlane best;
	best.candidates = pts.size();
	size_t bestScore = 0;
	const double minUp = std::cos(mrpt::DEG2RAD(o.maxNormalAngleDeg));
	std::mt19937 rng(o.seed);
	std::uniform_int_distribution<size_t> pick(0, pts.empty() ? 0 : pts.size() - 1);
	for (int it = 0; it < o.iterations && pts.size() >= 3; it++)
	{
		const auto &a = pts[pick(rng)], &b = pts[pick(rng)], &c = pts[pick(rng)];
		const Eigen::Vector3d cross = (b - a).cross(c - a);
		if (cross.norm() < 1e-9) continue;	// collinear or repeated points
		FloorPlane h = best;
		h.normal = upwards(cross.normalized());
		h.offset = -h.normal.dot(a);
		if (-h.normal.y() < minUp || h.offset <= 0) continue;
		const size_t score = countInliers(scoring, h, o.inlierBand);
		if (score > bestScore) bestScore = score, best = h;
	}
	// Refit until the inlier set settles (two or three rounds in practice).
	for (int round = 0; round < 10 && bestScore > 0; round++)
	{
		const size_t before = countInliers(pts, best, o.inlierBand);
		best = refit(pts, best, o.inlierBand);
		if (countInliers(pts, best, o.inlierBand) == before) break;
	}

	std::vector<double> residuals;
	if (bestScore > 0)
		for (const auto& p : pts)
			if (const double r = std::abs(best.height(p)); r <= o.inlierBand) residuals.push_back(r);
	best.inliers = residuals.size();
	double sumSq = 0;
	for (double r : residuals) sumSq += r * r;
	best.rms = residuals.empty() ? 0 : std::sqrt(sumSq / static_cast<double>(residuals.size()));
	best.medianResidual = lvf::common::upperMedian(residuals, 0.0);

	const double fraction = pts.empty() ? 0 : double(best.inliers) / double(pts.size());
	const std::string source = scene.file("disp0GT.pfm");
	if (best.inliers == 0)
		throw lvf::common::InputError(source, "", mrpt::format(
			"no floor visible: no plane within %.0f deg of level below the camera among the "
			"%zu ground-truth points below the image centre", o.maxNormalAngleDeg, pts.size()));
	// The refit may tip a plane through clutter past the priors its
	// hypothesis obeyed; a floor's stays put.
	if (-best.normal.y() < minUp || best.offset <= 0)
		throw lvf::common::InputError(source, "", mrpt::format(
			"no floor visible: the best near-level plane below the image centre (%zu of %zu "
			"ground-truth points within +-%.0f mm) tips to %.0f deg from level%s when refitted: "
			"clutter, not a floor",
			best.inliers, pts.size(), 1000 * o.inlierBand,
			mrpt::RAD2DEG(std::acos(std::clamp(-best.normal.y(), -1.0, 1.0))),
			best.offset <= 0 ? " and above the camera" : ""));
	if (fraction < o.minInlierFraction || best.medianResidual > o.maxMedianResidual)
		throw lvf::common::InputError(source, "", mrpt::format(
			"no floor visible: the best near-level plane below the image centre holds %zu of %zu "
			"ground-truth points (%.1f%%, a floor >= %.0f%%) within +-%.0f mm, median residual "
			"%.1f mm (a floor <= %.1f mm)",
			best.inliers, pts.size(), 100 * fraction, 100 * o.minInlierFraction,
			1000 * o.inlierBand, 1000 * best.medianResidual, 1000 * o.maxMedianResidual));
	return best;
}

}  // namespace lvf::middlebury
