#pragma once
// VFH+'s choice of a steering direction (Ulrich & Borenstein 1998, §2.4):
// the free openings ("valleys") of the masked histogram give candidate
// directions, and the candidate of least cost wins.
//  - narrow valley (at most s_max sectors): its centre;
//  - wide valley: its right border + s_max/2 and its left border - s_max/2
//    (keeping s_max/2 sectors of clearance from the obstacle), and the
//    target direction itself when it lies more than a margin inside the
//    borders (VFH+: the same s_max/2, i.e. between those two);
//  - cost g(c) = mu1 D(c, target) + mu2 D(c, heading) + mu3 D(c, previous),
//    D the difference in sectors the shorter way round.
// All positions are sector coordinates (PolarSectors): fractional, exact.

#include <lvfusion/vfh/PolarSectors.h>
#include <lvfusion/vfh/VfhParameters.h>

#include <cstdint>
#include <optional>
#include <vector>

namespace lvf::vfh
{
/** A run of free sectors, counter-clockwise from `first`. */
struct Valley
{
	size_t first = 0;  //!< right border (first free sector, ccw)
	size_t width = 0;  //!< free sectors; == count when nothing is blocked
};

struct Candidate
{
	double coordinate = 0;	//!< sector coordinate
	double cost = 0;		//!< VFH+ g(c)
};

/** The valleys of a masked histogram (1 = blocked), in ccw order of their
 * first sector. */
std::vector<Valley> findValleys(const std::vector<uint8_t>& masked);

/** Candidate directions of the valleys for a target at sector coordinate
 * `target` (VFH+ rules above, the target's margin `targetBorderSectors`,
 * plus: no blocked sector at all = the target direction alone). */
std::vector<double> candidateDirections(
	const std::vector<Valley>& valleys, const PolarSectors& sectors, double target,
	int wideValleySectors, int targetBorderSectors);

/** g(c) for the candidate at `c`. */
double steeringCost(
	double c, const PolarSectors& sectors, double target, double heading, double previous,
	const VfhParameters& p);

/** The candidates with their costs, and the cheapest (none if no valley). */
struct SteeringChoice
{
	std::vector<Candidate> candidates;
	std::optional<Candidate> best;
};
SteeringChoice chooseSteering(
	const std::vector<uint8_t>& masked, const PolarSectors& sectors, double target,
	double heading, double previous, const VfhParameters& p);

}  // namespace lvf::vfh
