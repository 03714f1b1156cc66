#include <lvfusion/vfh/PrimaryHistogram.h>
#include <lvfusion/vfh/VfhPlus.h>

#include <algorithm>

namespace lvf::vfh
{
VfhPlus::VfhPlus(const VfhParameters& p)
	: m_p(p), m_sectors(p.sectorCount()), m_binary(p.tauLow, p.tauHigh)
{
}

void VfhPlus::reset()
{
	m_binary.reset();
	m_previous.reset();
}

VfhPlus::Result VfhPlus::step(
	const std::vector<ObstacleCell>& cells, double targetDirection, double heading)
{
	Result r;
	r.primary = smoothHistogram(primaryHistogram(cells, m_sectors, m_p), m_p.smoothingL);
	r.binary = m_binary.update(r.primary);
	r.limits = turningLimits(cells, heading, m_p);
	r.masked = maskedHistogram(r.binary, m_sectors, heading, r.limits);
	r.valleys = findValleys(r.masked);
	r.targetCoordinate = m_sectors.coordinate(targetDirection);

	const double headingC = m_sectors.coordinate(heading);
	const double previousC = m_sectors.coordinate(m_previous.value_or(heading));
	const SteeringChoice choice =
		chooseSteering(r.masked, m_sectors, r.targetCoordinate, headingC, previousC, m_p);
	r.candidates = choice.candidates;
	if (!choice.best) return r;

	r.found = true;
	r.direction = m_sectors.angle(choice.best->coordinate);
	m_previous = r.direction;
	// VFH's speed law, with the density of the sector the robot is sent to.
	const double h = r.primary[m_sectors.sectorOf(r.direction)];
	r.speedFactor = 1.0 - std::min(h, m_p.speedDensityLimit) / m_p.speedDensityLimit;
	return r;
}

}  // namespace lvf::vfh
