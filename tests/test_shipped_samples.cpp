// The rawlogs in rawlog_samples/ are what rawlog_samples/regenerate.sh makes
// from today's world files and simulator (not stale: every frame's scan,
// images and odometry), and are complete.

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>

#include <fstream>

using namespace lvf::simulation;

class ShippedSample : public ::testing::TestWithParam<std::string>
{
   protected:
	/** The largest grey-level difference of two images of one size. */
	static double largestDifference(const mrpt::img::CImage& a, const mrpt::img::CImage& b)
	{
		cv::Mat diff;
		cv::absdiff(a.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), b.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY), diff);
		double largest = 0;
		cv::minMaxLoc(diff.reshape(1), nullptr, &largest);
		return largest;
	}
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

	// Every frame again, with the default sensors and seed, as regenerate.sh
	// does: the laser, both images and the odometry (each frame's action
	// holds the step from the reading before). The files must not be stale
	// in any of them: frame 0's scan and left image alone let an odometry
	// that changed go unnoticed.
	CStereoLaserSimulator sim(world, CStereoLaserSimulator::TOptions());
	mrpt::poses::CPose2D lastReading;
	for (size_t k = 0; k < world.path.size(); k++)
	{
		SCOPED_TRACE("frame " + std::to_string(k) + " (regenerate the samples: rawlog_samples/regenerate.sh)");
		const auto fresh = sim.simulateNextFrame(false);
		const auto sf = log.getAsObservations(2 * k + 1);
		const auto scan = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
		const auto stereo = sf->getObservationByClass<mrpt::obs::CObservationStereoImages>();
		ASSERT_TRUE(scan && stereo);
		ASSERT_EQ(scan->getScanSize(), fresh.scan->getScanSize());
		for (size_t i = 0; i < scan->getScanSize(); i++)
			EXPECT_NEAR(scan->getScanRange(i), fresh.scan->getScanRange(i), 1e-4) << i;
		EXPECT_LE(largestDifference(stereo->imageLeft, fresh.stereo->imageLeft), 1.0);
		EXPECT_LE(largestDifference(stereo->imageRight, fresh.stereo->imageRight), 1.0);
		if (k > 0)
		{
			const auto move = log.getAsAction(2 * k)->getBestMovementEstimation();
			ASSERT_TRUE(move);
			const mrpt::poses::CPose2D step = fresh.odometry - lastReading;
			EXPECT_NEAR(move->rawOdometryIncrementReading.x(), step.x(), 1e-6);
			EXPECT_NEAR(move->rawOdometryIncrementReading.y(), step.y(), 1e-6);
			EXPECT_NEAR(move->rawOdometryIncrementReading.phi(), step.phi(), 1e-6);
		}
		lastReading = fresh.odometry;
	}
}

INSTANTIATE_TEST_SUITE_P(
	Samples, ShippedSample, ::testing::Values("two_cubes", "box_room", "corridor_desk"),
	[](const auto& info) { return info.param; });
