// SeenSpace (libs/navigation): the band's voxels the cameras have looked
// through, against a scene worked out by hand -- a camera 1 m up, a box
// floating from 0.6 to 0.9 m at x = 2.0-2.6 m, the floor, a wall at 6 m.

#include <gtest/gtest.h>
#include <lvfusion/navigation/SeenSpace.h>

#include <algorithm>
#include <cmath>

namespace
{
using lvf::navigation::SeenSpace;
using mrpt::math::TPoint3D;

constexpr double kCameraHeight = 1.0, kBoxNear = 2.0, kBoxFar = 2.6, kBoxLow = 0.6, kBoxHigh = 0.9, kWall = 6.0;

/** Where the ray from the camera at elevation `a` (rad) first meets the box,
 * the floor or the wall, in the vertical plane y = `y`. */
TPoint3D firstHit(double a, double y)
{
	const double dx = std::cos(a), dz = std::sin(a);
	double t = (kWall - 0) / dx;  // the wall
	if (dz < 0) t = std::min(t, -kCameraHeight / dz);  // the floor
	// The box: its front face, then its top or bottom face.
	auto zAt = [&](double s) { return kCameraHeight + s * dz; };
	const double tFront = kBoxNear / dx;
	if (tFront < t && zAt(tFront) >= kBoxLow && zAt(tFront) <= kBoxHigh) t = tFront;
	for (const double face : {kBoxLow, kBoxHigh})
		if (dz != 0)
		{
			const double s = (face - kCameraHeight) / dz, x = s * dx;
			if (s > 0 && s < t && x >= kBoxNear && x <= kBoxFar) t = s;
		}
	return {t * dx, y, kCameraHeight + t * dz};
}

SeenSpace lookedAt()
{
	SeenSpace space(-1, 7, -1, 1, lvf::HeightBand{0.05, 1.2}, 0.05);
	for (double y = -0.1; y <= 0.1; y += 0.01)
		for (double deg = -45; deg <= 12; deg += 0.1)
			space.insertRay({0, y, kCameraHeight}, firstHit(deg * M_PI / 180, y));
	return space;
}
}  // namespace

TEST(SeenSpace, ColumnsAreSeenFreeOnlyWhereRaysCrossedTheWholeBand)
{
	const SeenSpace space = lookedAt();
	EXPECT_EQ(space.unseenHeight(1.5, 0), 0) << "in front of the box every height is crossed";
	EXPECT_NEAR(space.unseenHeight(2.3, 0), 0.3, 0.051) << "the box itself, 0.6-0.9 m";
	// Behind it the rays that pass under the box reach the floor, and those
	// over it the wall, but between them lies its shadow, bounded by the
	// rays through its lower front and upper far edges: 0.20-0.85 m at
	// x = 4, the floor's band edge (0.05) to 0.79 m at 5.5.
	EXPECT_NEAR(space.unseenHeight(4.0, 0), 0.65, 0.06);
	EXPECT_NEAR(space.unseenHeight(5.5, 0), 0.74, 0.06);
	EXPECT_NEAR(space.unseenHeight(1.5, 0.8), 1.15, 0.051) << "no ray went there: the whole band";
}

TEST(SeenSpace, TheRobotsBodyMarksItsColumnsFree)
{
	SeenSpace space = lookedAt();
	space.markFree({2.3, 0}, 0.3);
	EXPECT_EQ(space.unseenHeight(2.3, 0), 0);
	EXPECT_EQ(space.unseenHeight(2.3, 0.25), 0);
	EXPECT_GT(space.unseenHeight(2.3, 0.4), 0.2);
}
