#include <lvfusion/fusion/ModelWalls.h>

#include <cmath>

namespace lvf::fusion
{
std::vector<lvf::model::VerticalWall> modelWalls(
	const mrpt::obs::CObservation2DRangeScan& scan, const std::vector<lvf::lines::LineSegment>& segments,
	bool facetStrayReturns)
{
	std::vector<lvf::model::VerticalWall> walls;
	std::vector<bool> covered(scan.getScanSize(), false);
	for (const auto& s : segments)
	{
		walls.push_back({s.start, s.end});
		for (size_t i = s.firstIndex; i <= s.lastIndex && i < covered.size(); i++) covered[i] = true;
	}
	if (!facetStrayReturns || scan.getScanSize() < 2) return walls;
	const double step = scan.aperture / double(scan.getScanSize() - 1);
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
