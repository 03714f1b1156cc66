#pragma once
// VFH+'s primary polar histogram (Ulrich & Borenstein 1998, §2.1): every
// cell of the active window adds its magnitude m = c^2 (a - b d^2) to every
// sector within +-gamma of its direction, gamma = asin((r_r + d_s) / d) being
// the angle the cell subtends once enlarged by the robot radius plus the
// safety distance; optionally smoothed as in VFH (1991, eq. 5).

#include <lvfusion/vfh/ActiveWindow.h>
#include <lvfusion/vfh/PolarSectors.h>
#include <lvfusion/vfh/VfhParameters.h>

#include <vector>

namespace lvf::vfh
{
/** The primary histogram H^p of `cells` (densities per sector). Cells
 * beyond the window radius, or at the robot's very centre (no direction),
 * add nothing; cells nearer than r_r + d_s (already touching the enlarged
 * robot) block the half-plane towards them (gamma = 90 deg). */
std::vector<double> primaryHistogram(
	const std::vector<ObstacleCell>& cells, const PolarSectors& sectors, const VfhParameters& p);

/** VFH's weighted moving average over 2l-1 sectors, weights 1..l..1
 * (circular); l = 1 returns the histogram unchanged. */
std::vector<double> smoothHistogram(const std::vector<double>& h, int l);

}  // namespace lvf::vfh
