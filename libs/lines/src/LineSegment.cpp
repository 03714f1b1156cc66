#include <lvfusion/lines/LineSegment.h>

namespace lvf::lines
{
double LineSegment::length() const { return (end - start).norm(); }

Eigen::Vector2d LineSegment::direction() const
{
	const Eigen::Vector2d d = end - start;
	const double len = d.norm();
	// A zero-length segment still has a line: fall back to its direction.
	return len > 0 ? Eigen::Vector2d(d / len) : Eigen::Vector2d(-normal.y(), normal.x());
}

}  // namespace lvf::lines
