// VFH+ (lvf::vfh) on constructed obstacle layouts, every expected angle
// worked out by hand from the geometry and the published rules. With the
// defaults: 72 sectors of 5 deg, sector k centred at -180 + 5 (k + 0.5) deg
// (so straight ahead, 0 deg, is the border of sectors 35 and 36), cells
// enlarged by r_r + d_s = 0.36 m, so a cell at distance d blocks the sector
// centres within asin(0.36 / d) of its bearing; magnitude of a certain cell
// 2 - d^2 / 1.6^2 (1.61 at 1 m, above tau_high = 1); s_max = 16.

#include <gtest/gtest.h>
#include <lvfusion/vfh/PrimaryHistogram.h>
#include <lvfusion/vfh/VfhPlus.h>
#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>

using namespace lvf::vfh;
using mrpt::DEG2RAD;
using mrpt::RAD2DEG;

namespace
{
ObstacleCell at(double bearingDeg, double distance, double certainty = 1.0)
{
	return {distance * std::cos(DEG2RAD(bearingDeg)), distance * std::sin(DEG2RAD(bearingDeg)), certainty};
}

/** Certain cells every degree of [fromDeg, toDeg] at `distance`. */
void addArc(std::vector<ObstacleCell>& cells, int fromDeg, int toDeg, double distance)
{
	for (int a = fromDeg; a <= toDeg; a++) cells.push_back(at(a, distance));
}

/** One cycle of a fresh VFH+; returns the chosen direction [deg]. */
double steer(const std::vector<ObstacleCell>& cells, double targetDeg, VfhParameters p = {})
{
	VfhPlus vfh(p);
	const auto r = vfh.step(cells, DEG2RAD(targetDeg), 0.0);
	EXPECT_TRUE(r.found);
	return RAD2DEG(r.direction);
}
}  // namespace

TEST(VfhSectors, NumberedAsMrptDirections)
{
	const PolarSectors s(72);
	EXPECT_NEAR(RAD2DEG(s.centre(0)), -177.5, 1e-9);
	EXPECT_NEAR(RAD2DEG(s.centre(36)), 2.5, 1e-9);
	EXPECT_EQ(s.sectorOf(DEG2RAD(1.0)), 36u);
	EXPECT_EQ(s.sectorOf(DEG2RAD(-1.0)), 35u);
	EXPECT_EQ(s.sectorOf(M_PI), 0u);
	EXPECT_NEAR(s.coordinate(0.0), 35.5, 1e-9);
	EXPECT_NEAR(s.distance(1.0, 70.0), 3.0, 1e-9) << "the short way round";
}

TEST(VfhPrimaryHistogram, CellEnlargedByRobotRadiusPlusSafety)
{
	const VfhParameters p;
	const PolarSectors s(p.sectorCount());
	// A certain cell straight ahead at 1 m: gamma = asin(0.36) = 21.1 deg,
	// so the centres at +-2.5 .. +-17.5 deg (sectors 32..39) get m = 2 - 1/2.56.
	const auto h = primaryHistogram({at(0, 1.0)}, s, p);
	for (size_t k = 0; k < s.count(); k++)
		EXPECT_NEAR(h[k], (k >= 32 && k <= 39) ? 2.0 - 1.0 / 2.56 : 0.0, 1e-12) << k;
	// Beyond the window radius (1.6 m): nothing.
	const auto far = primaryHistogram({at(0, 1.7)}, s, p);
	for (double v : far) EXPECT_EQ(v, 0.0);
}

TEST(VfhPrimaryHistogram, SmoothingIsVfhWeightedAverage)
{
	// l = 2: h'_k = (h_{k-1} + 2 h_k + h_{k+1}) / 3.
	const auto out = smoothHistogram({0, 3, 0, 0, 0, 0}, 2);
	const std::vector<double> expected{1, 2, 1, 0, 0, 0};
	for (size_t k = 0; k < expected.size(); k++) EXPECT_NEAR(out[k], expected[k], 1e-12) << k;
}

TEST(VfhSteering, FreeSpaceAheadGoesStraightToTarget)
{
	VfhPlus vfh;
	const auto r = vfh.step({}, 0.0, 0.0);
	ASSERT_TRUE(r.found);
	EXPECT_NEAR(r.direction, 0.0, 1e-9);
	EXPECT_NEAR(r.speedFactor, 1.0, 1e-12) << "no obstacle density ahead";
}

TEST(VfhSteering, TargetToTheLeftWithFreeSpaceTurnsLeft)
{
	// An obstacle on the right (-90 deg, 1 m) blocks -107.5 .. -72.5 deg; the
	// target at 60 deg lies deep inside the wide valley: steer at it.
	EXPECT_NEAR(steer({at(-90, 1.0)}, 60.0), 60.0, 1e-9);
}

TEST(VfhSteering, NarrowValleySteersThroughItsCentre)
{
	// Walls all round at 1 m except the bearings 6..74 deg: cells at 5 and 75
	// deg block centres up to 26.1 and from 53.9 deg, leaving the six sectors
	// centred 27.5 .. 52.5 deg (< s_max): a narrow valley, centre 40 deg,
	// whatever the target inside it.
	std::vector<ObstacleCell> cells;
	addArc(cells, -180, 5, 1.0);
	addArc(cells, 75, 179, 1.0);
	VfhPlus vfh;
	const auto r = vfh.step(cells, DEG2RAD(30.0), 0.0);
	ASSERT_TRUE(r.found);
	ASSERT_EQ(r.valleys.size(), 1u);
	EXPECT_EQ(r.valleys[0].first, 41u);
	EXPECT_EQ(r.valleys[0].width, 6u);
	EXPECT_NEAR(RAD2DEG(r.direction), 40.0, 1e-9);
}

TEST(VfhSteering, WideValleySteersAtTargetSideBorderPlusHalfSmax)
{
	// One cell straight ahead at 1 m blocks -17.5 .. 17.5 deg; the target at
	// 5 deg is behind it. The valley (64 sectors) is wide: candidates 8
	// sectors inside its borders, 22.5 + 40 = 62.5 and -62.5 deg; the target
	// side (left) is cheaper: 5*11.5 + 2*12.5 + 2*12.5 vs 5*13.5 + 2*12.5 + 2*12.5.
	VfhPlus vfh;
	const auto r = vfh.step({at(0, 1.0)}, DEG2RAD(5.0), 0.0);
	ASSERT_TRUE(r.found);
	ASSERT_EQ(r.candidates.size(), 2u);
	EXPECT_NEAR(RAD2DEG(r.direction), 62.5, 1e-9);
	double costs[2] = {r.candidates[0].cost, r.candidates[1].cost};
	std::sort(costs, costs + 2);
	EXPECT_NEAR(costs[0], 107.5, 1e-9);
	EXPECT_NEAR(costs[1], 117.5, 1e-9);
}

TEST(VfhSteering, TargetNearAWideValleysBorderNeedsTheMargin)
{
	// The cell ahead at 1 m again: the left valley's border sector is
	// centred at 22.5 deg, and a target at 35 deg lies 2.5 sectors inside
	// it. VFH+'s margin (s_max/2 = 8 sectors) leaves the border candidate
	// 62.5 deg; a 1-sector margin adds the target itself, which costs least
	// (5*0 + 2*7 + 2*7 = 28 against 5*5.5 + 2*12.5 + 2*12.5 = 77.5).
	EXPECT_NEAR(steer({at(0, 1.0)}, 35.0), 62.5, 1e-9);
	VfhParameters p;
	p.targetBorderSectors = 1;
	EXPECT_NEAR(steer({at(0, 1.0)}, 35.0, p), 35.0, 1e-9);
	p.targetBorderSectors = 3;	// 2.5 sectors is not more than 3
	EXPECT_NEAR(steer({at(0, 1.0)}, 35.0, p), 62.5, 1e-9);
}

TEST(VfhSteering, PreviousDirectionKeepsTheChoice)
{
	// The cell ahead at 1 m again (candidates +-62.5 deg, sector coordinates
	// 48 and 23; heading 35.5). Target at +2.5 deg (coordinate 36): a fresh
	// VFH+ goes left, 5*12 + 2*12.5 + 2*12.5 = 110 against 5*13 + 25 + 25 =
	// 115. After a cycle that chose the right side (target at -2.5 deg) the
	// mu3 term makes leaving it cost 2*25 more: right 90, left 135.
	EXPECT_NEAR(steer({at(0, 1.0)}, 2.5), 62.5, 1e-9);
	VfhPlus vfh;
	EXPECT_NEAR(RAD2DEG(vfh.step({at(0, 1.0)}, DEG2RAD(-2.5), 0.0).direction), -62.5, 1e-9);
	const auto r = vfh.step({at(0, 1.0)}, DEG2RAD(2.5), 0.0);
	EXPECT_NEAR(RAD2DEG(r.direction), -62.5, 1e-9);
	double costs[2] = {r.candidates[0].cost, r.candidates[1].cost};
	std::sort(costs, costs + 2);
	EXPECT_NEAR(costs[0], 90.0, 1e-9);
	EXPECT_NEAR(costs[1], 135.0, 1e-9);
}

TEST(VfhSteering, TargetBehindWallPicksAValleyNotTheWall)
{
	// A wall across the way at x = 1 m, y in [-0.5, 0.5] (cells every 2 cm).
	// Its ends (1.118 m at +-26.6 deg, enlarged by asin(0.36/1.118) = 18.8
	// deg) block centres up to +-42.5 deg; the valley on the target's side
	// starts at 47.5 deg, so VFH+ steers at 47.5 + 40 = 87.5 deg.
	std::vector<ObstacleCell> cells;
	for (int i = -25; i <= 25; i++) cells.push_back({1.0, 0.02 * i, 1.0});
	VfhPlus vfh;
	const auto r = vfh.step(cells, DEG2RAD(10.0), 0.0);
	ASSERT_TRUE(r.found);
	EXPECT_TRUE(r.masked[vfh.sectors().sectorOf(DEG2RAD(10.0))]) << "the target is walled off";
	EXPECT_FALSE(r.masked[vfh.sectors().sectorOf(r.direction)]);
	EXPECT_NEAR(RAD2DEG(r.direction), 87.5, 1e-9);
}

TEST(VfhSteering, TargetBehindWallInAnOccupancyGrid)
{
	// The same from a COccupancyGridMap2D (10 cm cells): occupied cells with
	// centres x = 1.05, y = -0.45 .. 0.45. Ends at 1.142 m, +-23.2 deg,
	// enlarged by 18.4 deg: centres up to 37.5 deg blocked, valley from 42.5,
	// steer at 82.5 deg. Unknown cells (p = 0.5) must add nothing.
	mrpt::maps::COccupancyGridMap2D grid(-2, 2, -2, 2, 0.1f);
	for (int cy = grid.y2idx(-0.45); cy <= grid.y2idx(0.45); cy++) grid.setCell(grid.x2idx(1.05), cy, 0.0f);
	const auto cells = activeWindow(grid, {0, 0}, VfhParameters().windowRadius);
	EXPECT_EQ(cells.size(), 10u);
	EXPECT_NEAR(steer(cells, 10.0), 82.5, 1e-9);
}

TEST(VfhSteering, EverythingBlockedStops)
{
	std::vector<ObstacleCell> cells;
	addArc(cells, -180, 179, 1.0);
	VfhPlus vfh;
	const auto r = vfh.step(cells, 0.0, 0.0);
	EXPECT_FALSE(r.found);
	EXPECT_EQ(r.speedFactor, 0.0);
}

TEST(VfhSteering, SpeedFallsWithDensityInChosenDirection)
{
	// A faint cell (m = 0.4, below tau_low) straight at the target: the
	// direction stays free but the speed is 1 - 0.4 / h_m = 0.6.
	const double m1 = 2.0 - 1.0 / 2.56;	 // magnitude of a certain cell at 1 m
	VfhPlus vfh;
	const auto r = vfh.step({at(0, 1.0, std::sqrt(0.4 / m1))}, DEG2RAD(2.5), 0.0);
	ASSERT_TRUE(r.found);
	EXPECT_NEAR(RAD2DEG(r.direction), 2.5, 1e-9);
	EXPECT_NEAR(r.speedFactor, 0.6, 1e-9);
}

TEST(VfhBinaryHistogram, HysteresisKeepsStateBetweenThresholds)
{
	BinaryHistogram b(0.5, 1.0);
	EXPECT_EQ(b.update({0.7})[0], 0) << "starts free";
	EXPECT_EQ(b.update({1.2})[0], 1);
	EXPECT_EQ(b.update({0.7})[0], 1) << "between thresholds: stays blocked";
	EXPECT_EQ(b.update({0.4})[0], 0);
	EXPECT_EQ(b.update({0.9})[0], 0) << "between thresholds: stays free";
}

TEST(VfhBinaryHistogram, HysteresisAcrossCycles)
{
	// A cell at 1 m ahead whose magnitude falls from 1.61 (certain) to 0.75
	// (between tau_low and tau_high): still blocked in the second cycle, while
	// a fresh VFH+ seeing only the faint cell leaves it free.
	const double m1 = 2.0 - 1.0 / 2.56;
	const ObstacleCell faint = at(0, 1.0, std::sqrt(0.75 / m1));
	VfhPlus vfh;
	vfh.step({at(0, 1.0)}, 0.0, 0.0);
	const auto kept = vfh.step({faint}, 0.0, 0.0);
	EXPECT_NEAR(kept.primary[36], 0.75, 1e-9);
	EXPECT_TRUE(kept.binary[36]);
	EXPECT_NEAR(std::abs(RAD2DEG(kept.direction)), 62.5, 1e-9) << "still avoids the cell";

	VfhPlus fresh;
	const auto freed = fresh.step({faint}, 0.0, 0.0);
	EXPECT_FALSE(freed.binary[36]);
	EXPECT_NEAR(freed.direction, 0.0, 1e-9);
}

TEST(VfhMaskedHistogram, TurningRadiusBlocksDirectionsBeyondAnObstacle)
{
	// r_min = 0.5 m: the left trajectory circle is centred at (0, 0.5). A cell
	// at (0, 1.2) is 0.7 m from it, less than 0.5 + 0.36: the robot cannot
	// turn left past 90 deg. The cell itself blocks the centres within
	// asin(0.36 / 1.2) = 17.46 deg of 90, i.e. 77.5 .. 102.5 deg. Without the
	// mask the valley beyond it starts at 107.5 deg and the target at 150 deg
	// is 8.5 (> s_max/2) sectors inside: VFH+ steers straight at it. With the
	// mask every centre beyond 90 deg is blocked, the left valley ends at
	// 72.5 deg and the cheapest candidate is 72.5 - 40 = 32.5 deg (cost
	// 5*23.5 + 2*6.5 + 2*6.5 = 143.5 against 182.5 for -137.5 deg).
	VfhParameters p;
	const std::vector<ObstacleCell> cells{{0.0, 1.2, 1.0}};
	EXPECT_NEAR(steer(cells, 150.0, p), 150.0, 1e-9);

	p.minTurnRadius = 0.5;
	VfhPlus vfh(p);
	const auto r = vfh.step(cells, DEG2RAD(150.0), 0.0);
	ASSERT_TRUE(r.found);
	EXPECT_NEAR(RAD2DEG(r.limits.left), 90.0, 1e-9);
	EXPECT_NEAR(RAD2DEG(r.limits.right), -180.0, 1e-9) << "nothing on the right";
	for (size_t k = 0; k < vfh.sectors().count(); k++)
	{
		if (RAD2DEG(vfh.sectors().centre(k)) > 90.0) { EXPECT_TRUE(r.masked[k]) << k; }
	}
	EXPECT_FALSE(r.masked[vfh.sectors().sectorOf(DEG2RAD(-150.0))]);
	EXPECT_NEAR(RAD2DEG(r.direction), 32.5, 1e-9);
}

TEST(VfhMaskedHistogram, HeadingRotatesTheMask)
{
	// The same layout turned by 30 deg, robot heading 30 deg: the limit is at
	// 90 deg relative, 120 deg absolute.
	VfhParameters p;
	p.minTurnRadius = 0.5;
	const double h = DEG2RAD(30.0);
	const ObstacleCell cell{-1.2 * std::sin(h), 1.2 * std::cos(h), 1.0};
	const auto limits = turningLimits({cell}, h, p);
	EXPECT_NEAR(RAD2DEG(limits.left), 90.0, 1e-9);
}
