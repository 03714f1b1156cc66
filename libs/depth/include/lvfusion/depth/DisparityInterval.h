#pragma once
// Where on the epipolar line to look (paper §6.1, Fig. 6). In a rectified
// pair the epipolar line of a left pixel is its row in the right image, and a
// depth Z is the disparity d = fB / Z, so each criterion is a set of
// disparities:
//   a  |Z - Zl| >= d_allow       far enough from the laser model's depth Zl
//   b  Z <= Zl                   in front of the model (between p2 and the epipole)
//   c  Zmin <= Z <= Zmax         neither too near nor too far for the robot
//   band                        the point's height lies in the robot's band
// Their intersection is at most two intervals (a without b leaves both sides).
// (Where the model's surface is the floor, a can be narrowed to what matching
// cannot resolve, the band deciding: `floor_disparity_margin`.)

#include <array>
#include <cstddef>

namespace lvf::depth
{
struct Interval
{
	double lo = 0, hi = -1;	 //!< [lo, hi] in pixels of disparity; empty if lo > hi
	bool empty() const { return lo > hi; }
};

/** Up to two disjoint disparity intervals, in increasing order. */
class DisparitySet
{
   public:
	explicit DisparitySet(Interval all) { add(all); }
	/** Keeps only disparities inside `keep`. */
	void intersect(Interval keep);
	/** Removes the open interval (lo, hi). */
	void remove(double lo, double hi);

	size_t size() const { return m_count; }
	const Interval& operator[](size_t i) const { return m_intervals[i]; }
	bool empty() const { return m_count == 0; }
	/** Number of integer disparities inside. */
	size_t integerCount() const;

   private:
	void add(Interval i);
	std::array<Interval, 2> m_intervals;
	size_t m_count = 0;
};

}  // namespace lvf::depth
