// The model's walls from a scan: one per line segment, a join where two
// segments nearly meet on neighbouring rays, and a facet for each
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

TEST(ModelWalls, JoinsTheEndsOfSegmentsOnNeighbouringRaysWhereTheyNearlyMeet)
{
	// A room's corner 1.2 m ahead as the fit leaves it (overhang room 1 of
	// lvf-navigate, 34.8 s): the two walls' segments end 10 cm apart on
	// neighbouring rays. Then a segment on the next ray but one whose start
	// lies 0.5 m on (a box in front of the wall), and one with close ends
	// but five rays on (what lies between was not seen as a surface).
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = static_cast<float>(mrpt::DEG2RAD(60.0));
	scan.resizeScan(61);
	auto segment = [](Eigen::Vector2d a, Eigen::Vector2d b, size_t first, size_t last) {
		lvf::lines::LineSegment s;
		s.start = a, s.end = b, s.firstIndex = first, s.lastIndex = last;
		return s;
	};
	const std::vector<lvf::lines::LineSegment> segments{
		segment({1.12, -0.40}, {1.19, 0.47}, 0, 20),
		segment({1.21, 0.57}, {0.90, 0.62}, 21, 30),
		segment({0.60, 0.70}, {0.50, 0.75}, 32, 40),
		segment({0.48, 0.78}, {0.40, 0.80}, 46, 60),
	};
	const auto walls = lvf::fusion::modelWalls(scan, segments, false, 0.15);
	ASSERT_EQ(walls.size(), 5u);
	EXPECT_EQ(walls[4].start, segments[0].end);
	EXPECT_EQ(walls[4].end, segments[1].start);
	EXPECT_EQ(lvf::fusion::modelWalls(scan, segments, false, 0).size(), 4u) << "0: no joins";

	// A camera 1 m up at the robot's origin, looking through the slit half
	// a metre above the floor: the model's floor 2.6 m out without the
	// join, the join at 1.30 m with it.
	const Eigen::Vector3d camera(0, 0, 1), throughSlit(1.20, 0.52, 0.5);
	const Eigen::Vector3d dir = throughSlit - camera;
	const auto open = lvf::model::PlanarSceneModel(lvf::fusion::modelWalls(scan, segments, false, 0)).castRay(camera, dir);
	const auto joined = lvf::model::PlanarSceneModel(walls).castRay(camera, dir);
	EXPECT_EQ(open.surface, lvf::model::ModelHit::kFloor);
	EXPECT_EQ(joined.surface, 4);
	EXPECT_NEAR((joined.t * dir).head<2>().norm(), std::hypot(1.20, 0.52), 0.01);
}
