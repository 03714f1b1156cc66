// NarrowGapBridging: which gaps along an obstacle's edge are closed, and
// where the closed bearings end up, against the geometry of a straight edge.

#include <gtest/gtest.h>
#include <lvfusion/fusion/NarrowGapBridging.h>

#include <cmath>
#include <limits>
#include <vector>

using lvf::fusion::bridgeNarrowGaps;

namespace
{
constexpr float kNone = std::numeric_limits<float>::infinity();
const double kStep = M_PI / 180;  // 1-degree bearings
constexpr double kWidth = 0.15, kTolerance = 0.15;

/** Ranges of a straight edge square to bearing 0 at distance d (the bearings
 * -n..n), as the vector index 0..2n. */
std::vector<float> straightEdge(double d, int n)
{
	std::vector<float> r;
	for (int i = -n; i <= n; i++) r.push_back(static_cast<float>(d / std::cos(i * kStep)));
	return r;
}
}  // namespace

TEST(NarrowGapBridging, ClosesAGapInAnEdgeOntoTheEdgeItself)
{
	// An edge 2 m ahead seen by vision on 7 bearings but the middle 2
	// (3.5 cm each at 2 m: 10 cm between the ends, narrower than 0.15 m);
	// the laser passes under it to the wall at 6 m.
	const std::vector<float> edge = straightEdge(2.0, 3);
	std::vector<float> visual = edge;
	visual[3] = visual[4] = kNone;
	const std::vector<float> laser(7, 6.f);
	const std::vector<bool> bridged = bridgeNarrowGaps(visual, laser, kStep, kWidth, kTolerance);
	for (size_t i = 0; i < edge.size(); i++) EXPECT_NEAR(visual[i], edge[i], 1e-4) << "bearing " << i;
	EXPECT_EQ(bridged, (std::vector<bool>{false, false, false, true, true, false, false}));
}

TEST(NarrowGapBridging, ABearingThatVisionPlacedFartherBackTakesTheEdge)
{
	// The gap bearing holds a point on the top behind its front edge.
	const std::vector<float> edge = straightEdge(2.0, 2);
	std::vector<float> visual = edge;
	visual[2] = 2.4f;
	bridgeNarrowGaps(visual, std::vector<float>(5, 6.f), kStep, kWidth, kTolerance);
	EXPECT_NEAR(visual[2], 2.0, 1e-4);
}

TEST(NarrowGapBridging, LeavesGapsWiderThanTheWidthOpen)
{
	// Ends 4 bearings apart at 2.5 m: 0.17 m, wider than 0.15 m.
	std::vector<float> visual = straightEdge(2.5, 2);
	visual[1] = visual[2] = visual[3] = kNone;
	bridgeNarrowGaps(visual, std::vector<float>(5, 6.f), kStep, kWidth, kTolerance);
	EXPECT_TRUE(std::isinf(visual[1]) && std::isinf(visual[2]) && std::isinf(visual[3]));
	// The same gap at 1.5 m is 0.10 m wide: closed.
	visual = straightEdge(1.5, 2);
	visual[1] = visual[2] = visual[3] = kNone;
	bridgeNarrowGaps(visual, std::vector<float>(5, 6.f), kStep, kWidth, kTolerance);
	EXPECT_NEAR(visual[2], 1.5, 1e-4);
}

TEST(NarrowGapBridging, LeavesEndsAtDifferentRangesApart)
{
	// Two objects side by side, 2.0 and 2.3 m out: not one edge.
	std::vector<float> visual{2.0f, kNone, 2.3f};
	bridgeNarrowGaps(visual, std::vector<float>(3, 6.f), kStep, kWidth, kTolerance);
	EXPECT_TRUE(std::isinf(visual[1]));
}

TEST(NarrowGapBridging, LeavesTheLaserItsOwnGaps)
{
	// Two table legs the laser sees, nothing from vision: what the laser saw
	// between them at its height is a measurement, not a hole in an edge.
	std::vector<float> visual(3, kNone);
	bridgeNarrowGaps(visual, {2.0f, 6.0f, 2.0f}, kStep, kWidth, kTolerance);
	EXPECT_TRUE(std::isinf(visual[1]));
	// A leg by the laser and the top's edge by vision above it: one object.
	visual = {kNone, kNone, 2.0f};
	bridgeNarrowGaps(visual, {2.0f, 6.0f, 6.0f}, kStep, kWidth, kTolerance);
	EXPECT_NEAR(visual[1], 2.0 * std::cos(kStep), 1e-5);  // on the chord between the two
}

TEST(NarrowGapBridging, LeavesNearerObstaclesBetweenTheEndsAlone)
{
	// Something nearer than both ends stands between them: no gap, and its
	// own range must not be pushed back.
	std::vector<float> visual{2.0f, 1.2f, 2.0f};
	bridgeNarrowGaps(visual, std::vector<float>(3, 6.f), kStep, kWidth, kTolerance);
	EXPECT_FLOAT_EQ(visual[1], 1.2f);
}

TEST(NarrowGapBridging, KeepsWhatVisionPlacedOnTheSurfaceAlready)
{
	// The middle bearing's own visual range is 3 cm behind its neighbours',
	// within the tolerance: the same surface, not a gap; a wrong near range
	// at one end must not pull it in.
	std::vector<float> visual{2.00f, 2.05f, 1.90f};
	EXPECT_EQ(bridgeNarrowGaps(visual, std::vector<float>(3, 6.f), kStep, kWidth, kTolerance), std::vector<bool>(3, false));
	EXPECT_FLOAT_EQ(visual[1], 2.05f);
}
