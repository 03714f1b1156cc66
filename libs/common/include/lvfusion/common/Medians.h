#pragma once
// Medians of a handful of numbers, as the figures the programs report use
// them. By hand because neither MRPT nor OpenCV offers one for a plain
// vector (Eigen neither); each takes a copy, since nth_element reorders.

#include <algorithm>
#include <vector>

namespace lvf::common
{
/** The upper median (the element at index n / 2 of the sorted values):
 * always one of the values, as the metrics report a range that was measured;
 * `ifEmpty` for no values. */
template <typename T>
T upperMedian(std::vector<T> values, T ifEmpty)
{
	if (values.empty()) return ifEmpty;
	const auto mid = values.begin() + static_cast<long>(values.size() / 2);
	std::nth_element(values.begin(), mid, values.end());
	return *mid;
}

/** The median: for an even count, the mean of the two middle values (for
 * timings, where the centre of two is the better figure); `ifEmpty` for none. */
inline double median(std::vector<double> values, double ifEmpty)
{
	if (values.empty()) return ifEmpty;
	const auto mid = values.begin() + static_cast<long>(values.size() / 2);
	std::nth_element(values.begin(), mid, values.end());
	if (values.size() % 2) return *mid;
	return 0.5 * (*mid + *std::max_element(values.begin(), mid));
}

}  // namespace lvf::common
