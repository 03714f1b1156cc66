#include <lvfusion/vfh/MaskedHistogram.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace lvf::vfh
{
TurningLimits turningLimits(
	const std::vector<ObstacleCell>& cells, double heading, const VfhParameters& p)
{
	TurningLimits limits;
	const double r = p.minTurnRadius;
	if (r <= 0) return limits;
	const double reach = r + p.robotRadius + p.safetyDistance;
	const double c = std::cos(heading), s = std::sin(heading);
	for (const auto& cell : cells)
	{
		if (cell.certainty <= p.maskCertainty) continue;
		if (cell.dx * cell.dx + cell.dy * cell.dy > p.windowRadius * p.windowRadius) continue;
		// The cell in the robot's frame (x along the heading, y to its left);
		// the trajectory circles are centred at (0, r) and (0, -r).
		const double x = c * cell.dx + s * cell.dy, y = -s * cell.dx + c * cell.dy;
		const double bearing = std::atan2(y, x);
		if (bearing >= 0 && bearing < limits.left && x * x + (y - r) * (y - r) < reach * reach)
			limits.left = bearing;
		if (bearing <= 0 && bearing > limits.right && x * x + (y + r) * (y + r) < reach * reach)
			limits.right = bearing;
	}
	return limits;
}

std::vector<uint8_t> maskedHistogram(
	const std::vector<uint8_t>& binary, const PolarSectors& sectors, double heading,
	const TurningLimits& limits)
{
	std::vector<uint8_t> masked(binary);
	for (size_t k = 0; k < sectors.count(); k++)
	{
		const double rel = mrpt::math::wrapToPi(sectors.centre(k) - heading);
		if (rel > limits.left || rel < limits.right) masked[k] = 1;
	}
	return masked;
}

}  // namespace lvf::vfh
