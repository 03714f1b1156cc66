// The rawlogs in rawlog_samples/ are what rawlog_samples/regenerate.sh makes
// from today's world files and simulator (not stale), and are complete.

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <fstream>

using namespace lvf::simulation;

class ShippedSample : public ::testing::TestWithParam<std::string>
{
};

TEST_P(ShippedSample, MatchesAFreshSimulationOfItsWorld)
{
	const std::string name = GetParam();
	const World world = loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/" + name + ".yaml");
	mrpt::obs::CRawlog log;
	ASSERT_TRUE(log.loadFromRawLogFile(std::string(LVF_SAMPLES_DIR) + "/" + name + ".rawlog"));
	ASSERT_EQ(log.size(), 2 * world.path.size()) << "one action + one frame per pose";

	std::ifstream poses(std::string(LVF_SAMPLES_DIR) + "/" + name + "_gt_poses.txt");
	size_t poseLines = 0;
	for (std::string l; std::getline(poses, l);) poseLines += (!l.empty() && l[0] != '#');
	EXPECT_EQ(poseLines, world.path.size());

	// Frame 0 again, with the default sensors and seed, as regenerate.sh does.
	CStereoLaserSimulator sim(world, CStereoLaserSimulator::TOptions());
	const auto fresh = sim.simulateNextFrame(false);
	const auto sf = log.getAsObservations(1);
	const auto scan = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
	const auto stereo = sf->getObservationByClass<mrpt::obs::CObservationStereoImages>();
	ASSERT_TRUE(scan && stereo);
	ASSERT_EQ(scan->getScanSize(), fresh.scan->getScanSize());
	for (size_t i = 0; i < scan->getScanSize(); i++)
		EXPECT_NEAR(scan->getScanRange(i), fresh.scan->getScanRange(i), 1e-4) << i;
	cv::Mat diff;
	cv::absdiff(stereo->imageLeft.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY),
				fresh.stereo->imageLeft.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), diff);
	double maxDiff;
	cv::minMaxLoc(diff, nullptr, &maxDiff);
	EXPECT_LE(maxDiff, 1.0) << "regenerate the samples: rawlog_samples/regenerate.sh";
}

INSTANTIATE_TEST_SUITE_P(
	Samples, ShippedSample, ::testing::Values("two_cubes", "box_room", "corridor_desk"),
	[](const auto& info) { return info.param; });
