#include <lvfusion/vfh/SteeringSelection.h>

#include <cmath>

namespace lvf::vfh
{
std::vector<Valley> findValleys(const std::vector<uint8_t>& masked)
{
	const size_t n = masked.size();
	std::vector<Valley> valleys;
	size_t blocked = 0;
	while (blocked < n && !masked[blocked]) blocked++;
	if (blocked == n) return {Valley{0, n}};
	// Walk once round from a blocked sector, so that a valley across the
	// -pi/+pi seam comes out whole.
	for (size_t i = 1; i <= n; i++)
	{
		const size_t k = (blocked + i) % n;
		if (masked[k]) continue;
		if (masked[(k + n - 1) % n]) valleys.push_back({k, 0});
		valleys.back().width++;
	}
	return valleys;
}

std::vector<double> candidateDirections(
	const std::vector<Valley>& valleys, const PolarSectors& sectors, double target,
	int wideValleySectors, int targetBorderSectors)
{
	const double n = double(sectors.count());
	std::vector<double> out;
	for (const auto& v : valleys)
	{
		if (v.width == sectors.count())
		{
			out.push_back(target);
			continue;
		}
		const double right = double(v.first), left = right + double(v.width) - 1;
		auto wrapped = [&](double c) { return std::fmod(c + n + 0.5, n) - 0.5; };
		if (v.width <= size_t(wideValleySectors))
		{
			out.push_back(wrapped(0.5 * (right + left)));
			continue;
		}
		const double half = 0.5 * wideValleySectors;
		out.push_back(wrapped(right + half));
		out.push_back(wrapped(left - half));
		// The target, measured ccw from the right border, far enough inside.
		const double t = std::fmod(target - right + 2 * n, n), margin = targetBorderSectors;
		if (t > margin && t < double(v.width) - 1 - margin) out.push_back(wrapped(target));
	}
	return out;
}

double steeringCost(
	double c, const PolarSectors& sectors, double target, double heading, double previous,
	const VfhParameters& p)
{
	return p.mu1 * sectors.distance(c, target) + p.mu2 * sectors.distance(c, heading) +
		p.mu3 * sectors.distance(c, previous);
}

SteeringChoice chooseSteering(
	const std::vector<uint8_t>& masked, const PolarSectors& sectors, double target,
	double heading, double previous, const VfhParameters& p)
{
	SteeringChoice choice;
	for (double c : candidateDirections(findValleys(masked), sectors, target, p.wideValleySectors, p.targetBorderSectors))
	{
		const Candidate cand{c, steeringCost(c, sectors, target, heading, previous, p)};
		choice.candidates.push_back(cand);
		if (!choice.best || cand.cost < choice.best->cost) choice.best = cand;
	}
	return choice;
}

}  // namespace lvf::vfh
