#include <lvfusion/vfh/PolarSectors.h>
#include <mrpt/core/exceptions.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace lvf::vfh
{
PolarSectors::PolarSectors(size_t count) : m_count(count), m_width(2 * M_PI / double(count))
{
	ASSERT_(count >= 3);
}

double PolarSectors::centre(size_t k) const { return -M_PI + (double(k) + 0.5) * m_width; }

double PolarSectors::coordinate(double a) const
{
	double s = (mrpt::math::wrapToPi(a) + M_PI) / m_width - 0.5;
	// wrapToPi gives (-pi, pi]: +pi belongs to the first sector, as -pi.
	if (s >= double(m_count) - 0.5) s -= double(m_count);
	return s;
}

size_t PolarSectors::sectorOf(double a) const
{
	return wrap(std::lround(std::floor(coordinate(a) + 0.5)));
}

double PolarSectors::angle(double c) const
{
	return mrpt::math::wrapToPi(-M_PI + (c + 0.5) * m_width);
}

double PolarSectors::distance(double c1, double c2) const
{
	const double n = double(m_count);
	const double d = std::fmod(std::abs(c1 - c2), n);
	return std::min(d, n - d);
}

size_t PolarSectors::wrap(long k) const
{
	const long n = long(m_count);
	return size_t(((k % n) + n) % n);
}

}  // namespace lvf::vfh
