#pragma once
// Stage 5, after the per-bearing clusters: an obstacle's edge that vision
// found on some bearings and not on the ones between them is closed.
//
// The search samples every pixel_stride-th pixel and a table top's front
// edge is a few rows tall, so along an edge seen from 2-4 m vision finds it
// on most 1-degree bearings but not on all: between them the bin keeps a
// point farther back on the top (or none), and the laser passes under it.
// A gap that narrow is not a way through for any robot, and left open its
// rays would carve free space through the edge in the occupancy grid. So:
// where two bearings at most `width` apart (arc length at their range) have
// fused ranges that agree within `tolerance`, at least one of them set by
// vision, and every bearing between them is farther than both and not
// placed by vision on that surface already (within `tolerance` of the
// farther end), those bearings take the straight line between the two.
// (Measured: letting the line also replace vision's own ranges there spread
// a single wrong range into its correct neighbours -- box room phantom
// bearings 13 -> 15, StereoBM's scans 0.19 -> 0.31.)

#include <vector>

namespace lvf::fusion
{
/** @param visual per bearing, vision's range (+inf: none); bridged in place
 * @param laser per bearing, the laser's range (its max range where invalid)
 * @param bearingStep angle between consecutive bearings [rad]
 * @param width widest gap closed, as arc length between its ends [m]
 * @param tolerance the ends' ranges must agree within this [m]
 * @return per bearing, whether a bridge shortened its visual range */
std::vector<bool> bridgeNarrowGaps(
	std::vector<float>& visual, const std::vector<float>& laser, double bearingStep, double width,
	double tolerance);

}  // namespace lvf::fusion
