#pragma once
// The two scans the import derives from ground truth, both from the laser's
// origin (the robot origin, at the laser height, facing x) over the same
// bearings, with horizontal ranges (projected onto the floor) as a 2D scan's:
//  - the laser: per bearing, the nearest ground-truth point in a thin slice
//    around the laser height -- what a horizontal 2D laser there would see;
//  - the truth scan (DESIGN.md): per bearing, the nearest ground-truth point
//    anywhere in the robot's height band -- what the robot would run into.
// A point counts for the ray whose bearing is nearest its own, so the rays
// tile the aperture as a real scanner's beams (about one step wide) do.

#include <lvfusion/middlebury/MiddleburyCalib.h>
#include <lvfusion/middlebury/VirtualRobotFrame.h>

#include <lvfusion/common/HeightBand.h>
#include <lvfusion/common/LaserRange.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <Eigen/Core>
#include <vector>

namespace lvf::middlebury
{
struct ScanBearings
{
	double aperture = 0;  //!< [rad], centred on the robot's x axis
	size_t rays = 0;  //!< >= 2

	/** MRPT's convention (rightToLeft): ray i at -aperture/2 + i * step. */
	double bearing(size_t i) const { return -0.5 * aperture + step() * static_cast<double>(i); }
	double step() const { return lvf::rayStep(aperture, rays); }
	/** The ray nearest `bearing` [rad], or -1 more than half a step outside
	 * the aperture. */
	long rayOf(double bearing) const;

	/** `aperture` in steps of about `resolution`, as lvf-simulate's laser:
	 * round(aperture / resolution) + 1 rays. */
	static ScanBearings fromAperture(double aperture, double resolution);
};

/** Bearings covering the left camera's horizontal field of view (its image
 * borders seen from the robot origin), symmetric about x because the laser
 * faces x: twice the wider side, rounded up to a whole number of
 * `resolution` steps on each side.
 * Rays beyond the narrower side see no ground truth. */
ScanBearings cameraFieldOfView(
	const MiddleburyCalib& calib, const VirtualRobotFrame& frame, double resolution);

struct LaserSlice
{
	double height = 0.30;  //!< above the floor [m]
	/** Points within +-this of the height [m]: a pixel row spans Z/f, 3 mm
	 * at 3 m and 8 mm at 8 m here, so +-1 cm holds at least two rows of any
	 * surface crossing the slice out to the maximum range, and is still thin
	 * next to any obstacle. */
	double halfWidth = 0.01;
	double maxRange = 8.0;	//!< nothing nearer: no return [m]
};

/** The laser observation (label LASER, sensor at the origin at the slice's
 * height, rays without a return invalid at maxRange). */
mrpt::obs::CObservation2DRangeScan::Ptr synthesiseLaser(
	const std::vector<Eigen::Vector3d>& robotPoints, const ScanBearings& bearings,
	const LaserSlice& slice, mrpt::Clock::time_point stamp);

/** Per ray, the horizontal range to the nearest point in `band`; inf where
 * there is none. */
std::vector<float> truthScan(
	const std::vector<Eigen::Vector3d>& robotPoints, const ScanBearings& bearings,
	const lvf::HeightBand& band);

}  // namespace lvf::middlebury
