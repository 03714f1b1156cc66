#pragma once
// VFH+'s masked polar histogram (Ulrich & Borenstein 1998, §2.3). A vehicle
// that cannot turn on the spot moves along circles of radius >= r_min to
// either side; an obstacle cell closer than r_min + r_r + d_s to the centre
// of the left (right) circle blocks every direction beyond it on that side,
// even where the binary histogram is free, because the robot could not turn
// past the cell to reach them. The limits phi_l / phi_r start at the
// backward direction and shrink towards the heading with each such cell.

#include <lvfusion/vfh/ActiveWindow.h>
#include <lvfusion/vfh/PolarSectors.h>
#include <lvfusion/vfh/VfhParameters.h>

#include <cstdint>
#include <vector>

namespace lvf::vfh
{
struct TurningLimits
{
	/** Furthest reachable direction to the left / right of the heading,
	 * relative to it [rad]: left in [0, pi], right in [-pi, 0]. */
	double left = M_PI, right = -M_PI;
};

/** The limits that the cells more certain than p.maskCertainty impose on a
 * robot with heading `heading` (in the cells' frame) and turning radius
 * p.minTurnRadius on both sides. A radius of 0 (turning on the spot) imposes
 * none: the binary histogram already blocks the cells' own directions. */
TurningLimits turningLimits(
	const std::vector<ObstacleCell>& cells, double heading, const VfhParameters& p);

/** H^m: blocked (1) where the binary histogram is, or where the sector
 * centre lies outside [heading + right, heading + left]. */
std::vector<uint8_t> maskedHistogram(
	const std::vector<uint8_t>& binary, const PolarSectors& sectors, double heading,
	const TurningLimits& limits);

}  // namespace lvf::vfh
