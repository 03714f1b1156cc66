#pragma once
// What one laser bearing says, as the fusion, the metrics and the grids read
// it: a return is a range; no return means nothing up to the sensor's range.

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstddef>

namespace lvf
{
inline float laserRangeOrMax(const mrpt::obs::CObservation2DRangeScan& scan, size_t i)
{
	return scan.getScanRangeValidity(i) ? scan.getScanRange(i) : scan.maxRange;
}

}  // namespace lvf
