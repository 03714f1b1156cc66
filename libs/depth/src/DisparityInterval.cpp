#include <lvfusion/depth/DisparityInterval.h>

#include <algorithm>
#include <cmath>

namespace lvf::depth
{
void DisparitySet::add(Interval i)
{
	if (!i.empty() && m_count < m_intervals.size()) m_intervals[m_count++] = i;
}

void DisparitySet::intersect(Interval keep)
{
	size_t n = 0;
	for (size_t k = 0; k < m_count; k++)
	{
		Interval i{std::max(m_intervals[k].lo, keep.lo), std::min(m_intervals[k].hi, keep.hi)};
		if (!i.empty()) m_intervals[n++] = i;
	}
	m_count = n;
}

void DisparitySet::remove(double lo, double hi)
{
	std::array<Interval, 2> out;
	size_t n = 0;
	for (size_t k = 0; k < m_count; k++)
	{
		const Interval& i = m_intervals[k];
		// The parts of i left of lo and right of hi survive (at most two
		// pieces in all: the removed interval is a single gap).
		for (const Interval& piece : {Interval{i.lo, std::min(i.hi, lo)}, Interval{std::max(i.lo, hi), i.hi}})
			if (!piece.empty() && n < out.size()) out[n++] = piece;
	}
	m_intervals = out;
	m_count = n;
}

size_t DisparitySet::integerCount() const
{
	size_t n = 0;
	for (size_t k = 0; k < m_count; k++)
	{
		const double lo = std::ceil(m_intervals[k].lo), hi = std::floor(m_intervals[k].hi);
		if (hi >= lo) n += static_cast<size_t>(hi - lo) + 1;
	}
	return n;
}

}  // namespace lvf::depth
