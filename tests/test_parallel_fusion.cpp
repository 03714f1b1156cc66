// The model check and the focused search run their grid rows in bands on
// OpenCV's threads (RowBands.h). Each pixel is judged on its own, so the
// result must not depend on how many threads there are: the same states,
// scores, points (in the same order), outcomes and counts, bit for bit, as
// on one thread.

#include <gtest/gtest.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/RandomWorld.h>
#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <cstring>

using namespace lvf;

namespace
{
/** Runs `f` with OpenCV's pool at `threads`, then puts it back. */
template <typename F>
auto onThreads(int threads, F f)
{
	const int before = cv::getNumThreads();
	cv::setNumThreads(threads);
	auto result = f();
	cv::setNumThreads(before);
	return result;
}

bool sameBits(const cv::Mat& a, const cv::Mat& b)
{
	if (a.size() != b.size() || a.type() != b.type()) return false;
	for (int v = 0; v < a.rows; v++)
		if (std::memcmp(a.ptr(v), b.ptr(v), a.cols * a.elemSize()) != 0) return false;
	return true;
}

void expectSamePoints(const std::vector<depth::VisualPoint>& a, const std::vector<depth::VisualPoint>& b)
{
	ASSERT_EQ(a.size(), b.size());
	for (size_t i = 0; i < a.size(); i++)
	{
		EXPECT_EQ(a[i].u, b[i].u) << i;
		EXPECT_EQ(a[i].v, b[i].v) << i;
		EXPECT_EQ(a[i].disparity, b[i].disparity) << i;
		EXPECT_EQ(a[i].ncc, b[i].ncc) << i;
		EXPECT_EQ(a[i].robot, b[i].robot) << i;
	}
}

void expectSameStats(const depth::DepthSearchStats& a, const depth::DepthSearchStats& b)
{
	EXPECT_EQ(a.searchedPixels, b.searchedPixels);
	EXPECT_EQ(a.skippedUntextured, b.skippedUntextured);
	EXPECT_EQ(a.skippedEmptyRange, b.skippedEmptyRange);
	EXPECT_EQ(a.skippedBehindNearer, b.skippedBehindNearer);
	EXPECT_EQ(a.disparitiesTested, b.disparitiesTested);
	EXPECT_EQ(a.accepted, b.accepted);
	EXPECT_EQ(a.rejectedWeak, b.rejectedWeak);
	EXPECT_EQ(a.rejectedNotPeak, b.rejectedNotPeak);
	EXPECT_EQ(a.rejectedAmbiguous, b.rejectedAmbiguous);
	EXPECT_EQ(a.rejectedOutOfBand, b.rejectedOutOfBand);
	EXPECT_EQ(a.rejectedLeftRight, b.rejectedLeftRight);
	EXPECT_EQ(a.rejectedCore, b.rejectedCore);
}

/** Two frames of seeded room `seed` through the fusion as shipped, or with
 * `fullResolution` the search's full-resolution path. */
std::vector<fusion::CLaserStereoFusion::Result> fuseRoom(uint32_t seed, bool fullResolution)
{
	fusion::CLaserStereoFusion::TOptions options;
	options.depth.coarseToFine = !fullResolution;
	fusion::CLaserStereoFusion fusion(options);
	simulation::CStereoLaserSimulator sim(simulation::generateRandomWorld(seed), {});
	std::vector<fusion::CLaserStereoFusion::Result> out;
	for (int k = 0; k < 2; k++)
	{
		const auto f = sim.simulateNextFrame(false);
		out.push_back(fusion.process(*f.scan, *f.stereo, "frame", f.odometry));
	}
	return out;
}
}  // namespace

class ParallelFusion : public ::testing::TestWithParam<bool>
{
};

TEST_P(ParallelFusion, TheSameResultOnAnyNumberOfThreadsBitForBit)
{
	for (const uint32_t seed : {1u, 4u})
	{
		const auto one = onThreads(1, [&] { return fuseRoom(seed, GetParam()); });
		// Every core, at least two (TBB runs no more workers than cores):
		// bands of unequal row counts, several to a thread.
		const auto several = onThreads(std::max(2, cv::getNumberOfCPUs()), [&] { return fuseRoom(seed, GetParam()); });
		ASSERT_EQ(one.size(), several.size());
		for (size_t k = 0; k < one.size(); k++)
		{
			SCOPED_TRACE("room " + std::to_string(seed) + ", frame " + std::to_string(k));
			const auto &a = one[k], &b = several[k];
			EXPECT_TRUE(sameBits(a.evaluation.state, b.evaluation.state));
			EXPECT_TRUE(sameBits(a.evaluation.gridNcc, b.evaluation.gridNcc));
			EXPECT_TRUE(sameBits(a.evaluation.gridLeftMean, b.evaluation.gridLeftMean));
			EXPECT_TRUE(sameBits(a.evaluation.gridLeftStd, b.evaluation.gridLeftStd));
			EXPECT_EQ(a.evaluation.counts, b.evaluation.counts);
			EXPECT_TRUE(sameBits(a.search.outcome, b.search.outcome));
			expectSameStats(a.search.stats, b.search.stats);
			expectSamePoints(a.search.points, b.search.points);
			EXPECT_EQ(a.visualRanges, b.visualRanges);
			// Something to compare: the rooms hold obstacles vision finds.
			EXPECT_GT(a.search.stats.accepted, 100u);
		}
	}
}
INSTANTIATE_TEST_SUITE_P(Search, ParallelFusion, ::testing::Values(false, true),
	[](const auto& info) { return info.param ? "FullResolution" : "CoarseToFine"; });
