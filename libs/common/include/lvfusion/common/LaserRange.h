#pragma once
// What one laser bearing says, as the fusion, the metrics and the grids read
// it: a return is a range; no return means nothing up to the sensor's range.

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstddef>
#include <cmath>

namespace lvf
{
inline float laserRangeOrMax(const mrpt::obs::CObservation2DRangeScan& scan, size_t i)
{
	return scan.getScanRangeValidity(i) ? scan.getScanRange(i) : scan.maxRange;
}

/** Where a bearing in the sensor's frame [rad] falls among the scan's rays,
 * as a fractional index (0: the first ray, size - 1: the last, whichever way
 * the scan turns); rounded, the nearest ray, which may lie outside the scan. */
inline double rayIndexOf(const mrpt::obs::CObservation2DRangeScan& scan, double bearing)
{
	const size_t n = scan.getScanSize();
	const double step = n > 1 ? scan.aperture / static_cast<double>(n - 1) : 1.0;
	return ((scan.rightToLeft ? bearing : -bearing) + 0.5 * scan.aperture) / step;
}

}  // namespace lvf
