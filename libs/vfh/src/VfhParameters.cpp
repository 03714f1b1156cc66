#include <lvfusion/common/InputError.h>
#include <lvfusion/vfh/VfhParameters.h>

#include <cmath>
#include <tuple>

namespace lvf::vfh
{
using lvf::common::writeOption;

size_t VfhParameters::sectorCount() const { return size_t(std::lround(360.0 / sectorAngleDeg)); }

bool VfhParameters::operator==(const VfhParameters& o) const
{
	auto fields = [](const VfhParameters& p) {
		return std::tie(
			p.sectorAngleDeg, p.windowRadius, p.magnitudeA, p.robotRadius, p.safetyDistance,
			p.smoothingL, p.tauLow, p.tauHigh, p.maskCertainty, p.minTurnRadius,
			p.wideValleySectors, p.targetBorderSectors, p.mu1, p.mu2, p.mu3, p.speedDensityLimit);
	};
	return fields(*this) == fields(o);
}

double VfhParameters::magnitudeB() const
{
	return (magnitudeA - 1.0) / (windowRadius * windowRadius);
}

void VfhParameters::load(lvf::common::IniSection& ini, bool vehicleKeys)
{
	sectorAngleDeg = ini.real("sector_angle_deg", sectorAngleDeg, 0.5, 60);
	const double sectors = 360.0 / sectorAngleDeg;
	if (std::abs(sectors - std::round(sectors)) > 1e-9)
		throw lvf::common::InputError(
			ini.sourceName(), "[" + ini.section() + "] sector_angle_deg",
			"must divide 360 into whole sectors");
	windowRadius = ini.real("window_radius", windowRadius, 1e-6, 1e6);
	magnitudeA = ini.real("magnitude_a", magnitudeA, 1.0, 1e6);
	if (vehicleKeys) robotRadius = ini.real("robot_radius", robotRadius, 0, 1e6);
	safetyDistance = ini.real("safety_distance", safetyDistance, 0, 1e6);
	smoothingL = ini.integer("smoothing_l", smoothingL, 1, 36);
	tauLow = ini.real("tau_low", tauLow, 0, 1e9);
	tauHigh = ini.real("tau_high", tauHigh, tauLow, 1e9);
	maskCertainty = ini.real("mask_certainty", maskCertainty, 0, 1);
	if (vehicleKeys) minTurnRadius = ini.real("min_turn_radius", minTurnRadius, 0, 1e6);
	wideValleySectors = ini.integer("wide_valley_sectors", wideValleySectors, 1, int(sectorCount()));
	targetBorderSectors = ini.integer("target_border_sectors", targetBorderSectors, 0, int(sectorCount()) / 2);
	mu1 = ini.real("mu1", mu1, 0, 1e6);
	mu2 = ini.real("mu2", mu2, 0, 1e6);
	mu3 = ini.real("mu3", mu3, 0, 1e6);
	speedDensityLimit = ini.real("speed_density_limit", speedDensityLimit, 1e-9, 1e9);
}

void VfhParameters::save(
	mrpt::config::CConfigFileBase& c, const std::string& s, const std::string& unit,
	bool vehicleKeys) const
{
	writeOption(c, s, "sector_angle_deg", sectorAngleDeg, "polar histogram sector width alpha, divides 360 (VFH+: 5) [deg]");
	writeOption(c, s, "window_radius", windowRadius, "active window: cells farther than this are ignored (VFH: 33x33 cells of 0.1 m) [" + unit + "]");
	writeOption(c, s, "magnitude_a", magnitudeA, "magnitude c^2 (a - b d^2) with a - b window_radius^2 = 1 (VFH+): weight of a certain cell at the robot vs 1 at the edge");
	if (vehicleKeys)
		writeOption(c, s, "robot_radius", robotRadius, "obstacles enlarged by robot_radius + safety_distance (VFH+) [" + unit + "]");
	writeOption(c, s, "safety_distance", safetyDistance, "safety distance d_s: obstacle cells enlarged by the robot radius + d_s (VFH+) [" + unit + "]");
	writeOption(c, s, "smoothing_l", smoothingL, "VFH smoothing window l, 1 = none (VFH+ drops it; VFH used 5) [sectors]");
	writeOption(c, s, "tau_low", tauLow, "binary histogram: sectors below this are free (hysteresis, VFH+) [magnitude; 1 = certain cell at the edge]");
	writeOption(c, s, "tau_high", tauHigh, "binary histogram: sectors above this are blocked; in between keep their state [magnitude]");
	writeOption(c, s, "mask_certainty", maskCertainty, "cells more certain than this limit the turning directions (VFH+ masked histogram) [0-1]");
	if (vehicleKeys)
		writeOption(c, s, "min_turn_radius", minTurnRadius, "smallest turning radius, 0 = turns on the spot (no mask) [" + unit + "]");
	writeOption(c, s, "wide_valley_sectors", wideValleySectors, "s_max: wider openings are wide valleys, steered at border + s_max/2 (VFH+: 16) [sectors]");
	writeOption(c, s, "target_border_sectors", targetBorderSectors, "the target direction is a wide valley's candidate only this far inside its borders (VFH+: s_max/2 = 8) [sectors]");
	writeOption(c, s, "mu1", mu1, "cost weight of the target direction (VFH+: 5)");
	writeOption(c, s, "mu2", mu2, "cost weight of the current heading (VFH+: 2)");
	writeOption(c, s, "mu3", mu3, "cost weight of the previous direction (VFH+: 2)");
	writeOption(c, s, "speed_density_limit", speedDensityLimit, "h_m of VFH's speed law: speed = max (1 - min(h, h_m)/h_m) [magnitude]");
}

void VfhParameters::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	load(ini);
	ini.rejectUnknownKeys();
}

void VfhParameters::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& section) const
{
	save(c, section, "m");
}

}  // namespace lvf::vfh
