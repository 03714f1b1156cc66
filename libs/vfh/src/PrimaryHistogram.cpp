#include <lvfusion/vfh/PrimaryHistogram.h>

#include <cmath>

namespace lvf::vfh
{
std::vector<double> primaryHistogram(
	const std::vector<ObstacleCell>& cells, const PolarSectors& sectors, const VfhParameters& p)
{
	std::vector<double> h(sectors.count(), 0.0);
	const double a = p.magnitudeA, b = p.magnitudeB();
	const double enlarged = p.robotRadius + p.safetyDistance;
	const double rMax2 = p.windowRadius * p.windowRadius;
	for (const auto& cell : cells)
	{
		const double d2 = cell.dx * cell.dx + cell.dy * cell.dy;
		if (d2 > rMax2 || d2 == 0.0 || cell.certainty <= 0) continue;
		const double d = std::sqrt(d2);
		const double m = cell.certainty * cell.certainty * (a - b * d2);
		const double beta = std::atan2(cell.dy, cell.dx);
		const double gamma = d <= enlarged ? M_PI / 2 : std::asin(enlarged / d);
		// Sectors whose centre lies in [beta - gamma, beta + gamma] (VFH+),
		// and always the cell's own sector: with a small enlargement a cell
		// could otherwise fall between two centres and block nothing.
		const double c = sectors.coordinate(beta);
		const double halfWidth = gamma / sectors.width();
		const long first = long(std::ceil(c - halfWidth)), last = long(std::floor(c + halfWidth));
		for (long k = first; k <= last; k++) h[sectors.wrap(k)] += m;
		if (first > last) h[sectors.sectorOf(beta)] += m;
	}
	return h;
}

std::vector<double> smoothHistogram(const std::vector<double>& h, int l)
{
	if (l <= 1) return h;
	const long n = long(h.size());
	std::vector<double> out(h.size(), 0.0);
	for (long k = 0; k < n; k++)
	{
		double sum = 0;
		for (long i = -(l - 1); i <= l - 1; i++)
			sum += double(l - std::labs(i)) * h[size_t(((k + i) % n + n) % n)];
		out[size_t(k)] = sum / double(2 * l - 1);
	}
	return out;
}

}  // namespace lvf::vfh
