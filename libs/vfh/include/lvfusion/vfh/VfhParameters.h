#pragma once
// Parameters of the VFH+ obstacle-avoidance cycle (Ulrich & Borenstein,
// "VFH+: Reliable obstacle avoidance for fast mobile robots", ICRA 1998),
// which builds on VFH (Borenstein & Koren, "The vector field histogram - fast
// obstacle avoidance for mobile robots", IEEE T-RA 7(3), 1991), the method
// Baltzakis et al. modify in §6 of the paper.
//
// Lengths are in the units of the obstacle offsets given to VfhPlus: metres
// for a grid window (section [VfhPlus]), or fractions of the navigator's
// ref_distance when CHolonomicVFH runs in MRPT's normalised TP-space.
// Each default says where it comes from; where the papers give no number
// (thresholds and magnitudes depend on the certainty scale of the grid, tuned
// on the robot), the comment says what ours means.

#include <lvfusion/common/IniSection.h>
#include <mrpt/config/CLoadableOptions.h>

namespace lvf::vfh
{
struct VfhParameters : public mrpt::config::CLoadableOptions
{
	/** Sector width alpha [deg]; 360/alpha sectors. VFH+: 5 deg (72). */
	double sectorAngleDeg = 5.0;
	/** Radius of the active window around the robot: cells farther away
	 * are ignored [length]. VFH (1991): a 33 x 33 window of 10 cm cells, so
	 * 1.6 m from the centre to the edge. Ours is round (cells within the
	 * radius), so that reach does not depend on direction. */
	double windowRadius = 1.6;
	/** a of the VFH+ magnitude m = c^2 (a - b d^2), with b fixed by VFH+'s
	 * rule a - b d_max^2 = 1 (d_max = windowRadius): a certain cell at the
	 * window's edge weighs 1, one next to the robot weighs a. The paper
	 * gives no number; 2 is ours (nearer obstacles count up to twice). */
	double magnitudeA = 2.0;
	/** Robot radius r_r [length]: obstacle cells are enlarged by r_r + d_s
	 * (VFH+ §2.1). 0.26 m: the paper's iRobot B21r is about 52 cm across. */
	double robotRadius = 0.26;
	/** Safety distance d_s [length] added to the robot radius. 0.1 m: one
	 * cell of VFH's 10 cm grid. */
	double safetyDistance = 0.10;
	/** Smoothing window l of VFH (1991, eq. 5) [sectors]; 1 = none. VFH+
	 * drops the smoothing because the enlargement by r_r + d_s does its job
	 * (VFH used l = 5). */
	int smoothingL = 1;
	/** Hysteresis thresholds of the binary histogram (VFH+ §2.2): a sector
	 * denser than tauHigh is blocked, one below tauLow free, in between it
	 * keeps its previous state. Units of magnitude: 1 = one certain cell at
	 * the window's edge. The paper tunes them on its robot; ours block a
	 * sector as soon as one certain cell (anywhere in the window) or a few
	 * uncertain ones fall in it, and free it when less than half that is
	 * left. */
	double tauLow = 0.5;
	double tauHigh = 1.0;
	/** Cells with certainty above this count as obstacles for the turning
	 * limits of the masked histogram (VFH+ §2.3's threshold tau). */
	double maskCertainty = 0.5;
	/** Smallest turning radius of the vehicle [length] (VFH+ §2.3: r = v /
	 * omega_max). 0 = turns on the spot, as the paper's synchro-drive B21r
	 * does; the masked histogram then equals the binary one. */
	double minTurnRadius = 0.0;
	/** s_max [sectors]: openings wider than this are "wide" valleys (VFH+
	 * §2.4: 16 sectors of 5 deg). */
	int wideValleySectors = 16;
	/** In a wide valley the target direction itself is a candidate only if
	 * it lies more than this inside the valley's borders [sectors]. VFH+
	 * §2.4: s_max/2 (8), the same clearance as its border candidates, so
	 * that near an obstacle the robot steers 40 deg off it rather than at
	 * the target. Smaller margins steer straighter at the target: shorter
	 * paths, less room for what vision missed (measured:
	 * share/doc/lvfusion/measurements.md, lvf-navigate). */
	int targetBorderSectors = 8;
	/** Cost weights (VFH+ §2.4): target, current heading, previous choice.
	 * VFH+: mu1 = 5, mu2 = 2, mu3 = 2 (goal-oriented: mu1 > mu2 + mu3). */
	double mu1 = 5.0, mu2 = 2.0, mu3 = 2.0;
	/** h_m of VFH's speed law (1991, §4): speed = v_max (1 - min(h_c, h_m) /
	 * h_m), h_c the density in the chosen direction. "Empirically
	 * determined"; ours = tauHigh, so the robot slows to a stop as the
	 * density ahead reaches the blocking threshold. */
	double speedDensityLimit = 1.0;

	size_t sectorCount() const;
	bool operator==(const VfhParameters& o) const;
	/** b of the magnitude: a - b * windowRadius^2 = 1. */
	double magnitudeB() const;

	/** Reads the keys from an open section (the caller rejects unknown
	 * keys). `vehicleKeys` = false leaves robot_radius and min_turn_radius
	 * out, for CHolonomicVFH where the PTG already models the robot. */
	void load(lvf::common::IniSection& ini, bool vehicleKeys = true);
	void save(
		mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& lengthUnit,
		bool vehicleKeys = true) const;

	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void saveToConfigFile(
		mrpt::config::CConfigFileBase& target, const std::string& section) const override;
};

}  // namespace lvf::vfh
