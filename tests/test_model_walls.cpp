// The model's walls from a scan: one per line segment, plus a facet for each
// return no segment took, checked against hand-computed geometry.

#include <gtest/gtest.h>
#include <lvfusion/fusion/ModelWalls.h>
#include <mrpt/core/bits_math.h>

#include <cmath>

namespace
{
/** A 5-ray scan over 4 deg (1 deg apart), its sensor 0.2 m ahead of the
 * robot origin and 0.3 m up; rays 0-2 make a segment, 3 and 4 are strays
 * (ray 4 invalid). */
mrpt::obs::CObservation2DRangeScan scanWithStrays()
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(mrpt::DEG2RAD(4.0));
	scan.rightToLeft = true;
	scan.sensorPose = mrpt::poses::CPose3D(0.2, 0, 0.3, 0, 0, 0);
	scan.resizeScan(5);
	for (size_t i = 0; i < 5; i++)
	{
		scan.setScanRange(i, 2.0f);
		scan.setScanRangeValidity(i, i != 4);
	}
	return scan;
}
}  // namespace

TEST(ModelWalls, OneWallPerSegmentAndANarrowFacetPerStrayReturn)
{
	const auto scan = scanWithStrays();
	lvf::lines::LineSegment segment;
	segment.start = {2.2, -0.07}, segment.end = {2.2, 0.0};
	segment.firstIndex = 0, segment.lastIndex = 2;

	const auto plain = lvf::fusion::modelWalls(scan, {segment}, false);
	ASSERT_EQ(plain.size(), 1u);
	EXPECT_EQ(plain[0].start, segment.start);
	EXPECT_EQ(plain[0].end, segment.end);

	const auto walls = lvf::fusion::modelWalls(scan, {segment}, true);
	ASSERT_EQ(walls.size(), 2u) << "ray 3 is a stray return, ray 4 has none";
	// Ray 3 points at +1 deg (rays span -2..+2 deg); its return lies 2 m
	// from the sensor, the facet is square to the ray and 2 m * 1 deg wide.
	const double bearing = mrpt::DEG2RAD(1.0), width = 2.0 * mrpt::DEG2RAD(1.0);
	const Eigen::Vector2d hit(0.2 + 2.0 * std::cos(bearing), 2.0 * std::sin(bearing));
	const Eigen::Vector2d ray(std::cos(bearing), std::sin(bearing));
	const auto& facet = walls[1];
	// (1e-6: MRPT stores the aperture as a float.)
	EXPECT_NEAR((0.5 * (facet.start + facet.end) - hit).norm(), 0, 1e-6);
	EXPECT_NEAR((facet.end - facet.start).norm(), width, 1e-6);
	EXPECT_NEAR((facet.end - facet.start).dot(ray), 0, 1e-6);
}
