#pragma once
// The angular sectors of a VFH polar histogram, numbered as MRPT numbers the
// directions of its holonomic methods (NavInput::obstacles): sector 0 starts
// at -pi, sectors run counter-clockwise, sector k is centred at
// -pi + (k + 0.5) * alpha. Positions between sector centres are "sector
// coordinates": s = k at the centre of sector k, fractional in between, so
// that VFH+'s candidate directions (a valley's centre, a border + s_max/2)
// and its cost function (differences in sectors) need no rounding.

#include <cstddef>

namespace lvf::vfh
{
class PolarSectors
{
   public:
	/** `count` sectors of 2*pi/count each (VFH+: 72 sectors of 5 deg). */
	explicit PolarSectors(size_t count);

	size_t count() const { return m_count; }
	double width() const { return m_width; }  //!< alpha [rad]

	/** Centre of sector k [rad], in (-pi, pi). */
	double centre(size_t k) const;
	/** The sector an angle falls in (any angle, wrapped). */
	size_t sectorOf(double angle) const;
	/** Sector coordinate of an angle, in [-0.5, count - 0.5). */
	double coordinate(double angle) const;
	/** Angle [rad] of a sector coordinate, wrapped to (-pi, pi]. */
	double angle(double coordinate) const;
	/** VFH+'s Delta(c1, c2): the shorter way round between two sector
	 * coordinates, in sectors (0 .. count/2). */
	double distance(double c1, double c2) const;
	/** Wraps a (possibly negative) sector index into 0 .. count-1. */
	size_t wrap(long k) const;

   private:
	size_t m_count;
	double m_width;
};

}  // namespace lvf::vfh
