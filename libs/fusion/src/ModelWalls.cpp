#include <lvfusion/common/LaserRange.h>
#include <lvfusion/fusion/ModelWalls.h>

#include <algorithm>
#include <cmath>

namespace lvf::fusion
{
std::vector<lvf::model::VerticalWall> modelWalls(
	const mrpt::obs::CObservation2DRangeScan& scan, const std::vector<lvf::lines::LineSegment>& segments,
	bool facetStrayReturns, double joinGap)
{
	std::vector<lvf::model::VerticalWall> walls;
	std::vector<bool> covered(scan.getScanSize(), false);
	for (const auto& s : segments)
	{
		walls.push_back({s.start, s.end});
		for (size_t i = s.firstIndex; i <= s.lastIndex && i < covered.size(); i++) covered[i] = true;
	}
	if (joinGap > 0)
	{
		std::vector<const lvf::lines::LineSegment*> inScanOrder;
		for (const auto& s : segments) inScanOrder.push_back(&s);
		std::sort(inScanOrder.begin(), inScanOrder.end(), [](auto* a, auto* b) { return a->firstIndex < b->firstIndex; });
		for (size_t k = 1; k < inScanOrder.size(); k++)
		{
			const auto &before = *inScanOrder[k - 1], &after = *inScanOrder[k];
			if (after.firstIndex <= before.lastIndex + 2 && (after.start - before.end).norm() <= joinGap)
				walls.push_back({before.end, after.start});
		}
	}
	if (!facetStrayReturns || scan.getScanSize() < 2) return walls;
	const double step = rayStep(scan.aperture, scan.getScanSize());
	for (size_t i = 0; i < scan.getScanSize(); i++)
	{
		if (covered[i] || !scan.getScanRangeValidity(i)) continue;
		const double range = scan.getScanRange(i), bearing = scan.getScanAngle(i);
		const double halfWidth = 0.5 * range * step;
		// The return and the facet's two ends, in the sensor's plane...
		const mrpt::math::TPoint3D ends[2] = {
			{range * std::cos(bearing) - halfWidth * std::sin(bearing), range * std::sin(bearing) + halfWidth * std::cos(bearing), 0},
			{range * std::cos(bearing) + halfWidth * std::sin(bearing), range * std::sin(bearing) - halfWidth * std::cos(bearing), 0}};
		// ...then on the robot.
		const auto a = scan.sensorPose.composePoint(ends[0]), b = scan.sensorPose.composePoint(ends[1]);
		walls.push_back({{a.x, a.y}, {b.x, b.y}});
	}
	return walls;
}

}  // namespace lvf::fusion
