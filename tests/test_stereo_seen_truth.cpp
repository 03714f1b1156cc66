// The seen truth scan (StereoSeenTruth.h): the truth scan of the obstacles
// both cameras see. A box in front of the rig is seen at its true range; a
// pole at the left image's edge, which the right camera (12 cm to the right)
// does not see, is a hidden bearing no stereo method can recall.

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <mrpt/core/bits_math.h>

#include <cmath>

using namespace lvf::simulation;
using lvf::test::noiseFreeOptions;
using lvf::test::roomWorld;
using lvf::test::worldFromText;

namespace
{
const std::string kBoxAhead = "  - {pose: [2, 0, 0], size: [0.4, 0.4, 0.5]}\n";
const std::string kPoleAtTheLeftEdge = "  - {pose: [1.0, 0.75, 0], size: [0.06, 0.06, 0.5], elevation: 0.4}\n";

CStereoLaserSimulator::Frame frameOf(const std::string& boxes)
{
	CStereoLaserSimulator sim(worldFromText(roomWorld(boxes)), noiseFreeOptions());
	return sim.simulateNextFrame(true);
}

size_t rayAt(const CStereoLaserSimulator::Frame& f, double bearingDeg)
{
	return static_cast<size_t>(std::lround((mrpt::DEG2RAD(bearingDeg) - f.scan->getScanAngle(0)) /
		(f.scan->aperture / double(f.scan->getScanSize() - 1))));
}
}  // namespace

TEST(StereoSeenTruth, IsTheTruthWhereBothCamerasSeeTheObstacle)
{
	const auto f = frameOf(kBoxAhead);
	ASSERT_EQ(f.seenTruthScan.size(), f.truthScan.size());
	// The box's front face, x = 1.8, seen from the laser at x = 0.15.
	for (double deg = -5; deg <= 5; deg += 1)
	{
		const size_t i = rayAt(f, deg);
		EXPECT_NEAR(f.truthScan[i], 1.65 / std::cos(mrpt::DEG2RAD(deg)), 0.01) << deg;
		EXPECT_NEAR(f.seenTruthScan[i], f.truthScan[i], 0.01) << deg;
	}
	// Behind the rig nothing is seen; the room's walls are there all the same.
	EXPECT_TRUE(std::isfinite(f.truthScan[rayAt(f, 90)]));
	EXPECT_FALSE(std::isfinite(f.seenTruthScan[rayAt(f, 90)]));
}

TEST(StereoSeenTruth, LeavesOutWhatTheRightCameraDoesNotSee)
{
	const auto withPole = frameOf(kPoleAtTheLeftEdge);
	const auto without = frameOf("");
	// The pole is in the left image, in its leftmost columns only: at about
	// 1 m its disparity (fB / z = 54 px) puts it left of the right image.
	int changedMinCol = withPole.leftDepth.cols, changedMaxCol = -1;
	for (int v = 0; v < withPole.leftDepth.rows; v++)
		for (int u = 0; u < withPole.leftDepth.cols; u++)
			if (std::abs(withPole.leftDepth(v, u) - without.leftDepth(v, u)) > 0.01f)
				changedMinCol = std::min(changedMinCol, u), changedMaxCol = std::max(changedMaxCol, u);
	ASSERT_GE(changedMaxCol, 0) << "the pole is not in the left image";
	EXPECT_EQ(changedMinCol, 0);
	EXPECT_LT(changedMaxCol, 54);

	const lvf::HeightBand band;
	const auto inView = lvf::metrics::bearingsInView(*withPole.scan, withPole.truthScan, *withPole.stereo, band, 5.0);
	const auto hidden = lvf::metrics::hiddenBearings(*withPole.scan, withPole.truthScan, inView);
	size_t poleBearings = 0;
	for (double deg = 38; deg <= 45; deg += 1)
	{
		const size_t i = rayAt(withPole, deg);
		if (!hidden[i]) continue;  // the pole: hidden from the laser (below its 0.4 m), in the left view
		poleBearings++;
		EXPECT_LT(withPole.truthScan[i], 1.2) << deg;
		EXPECT_GT(withPole.seenTruthScan[i], withPole.truthScan[i] + 0.10) << deg;
	}
	EXPECT_GE(poleBearings, 2u);
}
