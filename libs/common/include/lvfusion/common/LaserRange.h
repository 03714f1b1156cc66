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

/** The angle between neighbouring rays of `rays` rays over `aperture`
 * [rad], MRPT's convention (the first and last at the aperture's ends); 1
 * for a single ray. */
inline double rayStep(double aperture, size_t rays)
{
	return rays > 1 ? aperture / static_cast<double>(rays - 1) : 1.0;
}

/** Where a bearing [rad, counter-clockwise] falls among `rays` rays spread
 * right to left over `aperture` [rad] centred on 0, as a fractional index
 * (0: the rightmost ray); rounded, the nearest ray, which may lie outside. */
inline double rayIndexOf(double aperture, size_t rays, double bearing)
{
	return (bearing + 0.5 * aperture) / rayStep(aperture, rays);
}

/** Where a bearing in the sensor's frame [rad] falls among the scan's rays,
 * as a fractional index (0: the first ray, size - 1: the last, whichever way
 * the scan turns); rounded, the nearest ray, which may lie outside the scan. */
inline double rayIndexOf(const mrpt::obs::CObservation2DRangeScan& scan, double bearing)
{
	return rayIndexOf(scan.aperture, scan.getScanSize(), scan.rightToLeft ? bearing : -bearing);
}

}  // namespace lvf
