#pragma once
// The floor under a Middlebury scene, fitted to its ground-truth points:
// RANSAC for the plane, then a least-squares refit on its inliers.
//
// Hand-written on Eigen: OpenCV has no plane RANSAC, and MRPT's
// ransac_detect_3D_planes peels off every plane in turn, draws from MRPT's
// global random generator and keeps the three-point plane. Here the fit has
// a fixed seed (an import is reproducible), knows which way is up (a floor's
// normal is near the camera's -y and the camera is above it, which rules out
// walls and ceilings), and refits by total least squares with Eigen's
// SelfAdjointEigenSolver.

#include <lvfusion/middlebury/MiddleburyScene.h>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>

namespace lvf::middlebury
{
struct FloorPlane
{
	/** Unit normal in the left camera's frame, pointing to the camera's
	 * side of the floor (roughly the camera's -y). */
	Eigen::Vector3d normal = -Eigen::Vector3d::UnitY();
	/** normal . p + offset = 0 on the floor; offset is the camera's height
	 * above it [m]. */
	double offset = 0;
	size_t candidates = 0;	//!< ground-truth points the fit looked at
	size_t inliers = 0;	 //!< of those, within the inlier band of the plane
	double rms = 0;	 //!< RMS distance of the inliers to the plane [m]
	double medianResidual = 0;	//!< median |distance| of the inliers [m]

	/** Signed height of a camera-frame point above the floor [m]. */
	double height(const Eigen::Vector3d& p) const { return normal.dot(p) + offset; }
};

struct FloorFitOptions
{
	/** Inliers lie within +-this of the plane [m]: several times the few
	 * millimetres by which a real floor's ground-truth points scatter, so
	 * the whole floor is in, yet narrow next to the objects standing on it. */
	double inlierBand = 0.02;
	/** The normal within this of the camera's up axis (-y) [deg], tilt and
	 * roll together: a robot's camera looks roughly forward, never straight
	 * down at the floor. */
	double maxNormalAngleDeg = 45;
	/** A floor fills the bottom of a forward-looking camera's image: at
	 * least this fraction of the candidate points must be inliers. */
	double minInlierFraction = 0.10;
	/** A plane, not a slab: points spread evenly through the band (clutter
	 * that happens to fit it) have a median |residual| of half the band,
	 * 10 mm; a floor's is set by ground-truth noise and flatness, ~2 mm
	 * (Motorcycle 2.1, Recycle 2.4; the best planes of the other scenes,
	 * table tops and clutter, 5.4 to 9.7): at most twice a floor's. */
	double maxMedianResidual = 0.004;
	/** RANSAC hypotheses: a floor holding the minimum fraction is drawn
	 * whole (three inliers) with p = 0.001 per hypothesis, so 5000 miss it
	 * with probability e^-5 < 1%. */
	int iterations = 5000;
	size_t maxScoringPoints = 20000;  //!< hypotheses are scored on an even subsample
	uint32_t seed = 1;
};

/** Fits the floor to the scene's ground-truth points below the principal
 * row (v > cy): with the camera level or looking down these pixels all see
 * below the horizon, where the floor is. Throws InputError naming the
 * disparity file ("no floor visible: ...", with the best plane's figures)
 * when no plane passes the options' tests. */
FloorPlane fitFloor(const MiddleburyScene& scene, const FloorFitOptions& options = {});

}  // namespace lvf::middlebury
