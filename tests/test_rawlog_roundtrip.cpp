// Rawlogs written by the simulator read back through MRPT unchanged, in both
// layouts -- written as several gzip members (GzWriterThread.h), which
// MRPT reads as one stream; a seed fixes every bit of the output; a file
// that cannot be written is reported.

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogWriter.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/system/filesystem.h>

#include <zlib.h>

#include <filesystem>
#include <fstream>
#include <iterator>

using namespace lvf::simulation;
using lvf::common::RawlogFormat;

namespace
{
/** The gzip members the file at `path` holds, one after another. */
int gzipMembers(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), {});
	std::vector<unsigned char> out(1 << 16);
	int members = 0;
	size_t at = 0;
	while (at < bytes.size())
	{
		z_stream z{};
		if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) return -1;
		z.next_in = bytes.data() + at;
		z.avail_in = static_cast<uInt>(bytes.size() - at);
		int result;
		do
		{
			z.next_out = out.data();
			z.avail_out = static_cast<uInt>(out.size());
			result = inflate(&z, Z_NO_FLUSH);
		} while (result == Z_OK);
		at += z.total_in;
		inflateEnd(&z);
		if (result != Z_STREAM_END) return -1;
		members++;
	}
	return members;
}

std::vector<CStereoLaserSimulator::Frame> simulate(uint32_t seed, size_t frames)
{
	World world = loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml");
	world.path.resize(frames);
	CStereoLaserSimulator::TOptions opt;
	opt.seed = seed;
	CStereoLaserSimulator sim(world, opt);
	std::vector<CStereoLaserSimulator::Frame> out;
	for (size_t k = 0; k < frames; k++) out.push_back(sim.simulateNextFrame(false));
	return out;
}

bool sameImage(const mrpt::img::CImage& a, const mrpt::img::CImage& b)
{
	const cv::Mat ma = a.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	const cv::Mat mb = b.asCvMat<cv::Mat>(mrpt::img::SHALLOW_COPY);
	return ma.size() == mb.size() && ma.type() == mb.type() &&
		cv::countNonZero(ma != mb) == 0;
}

void expectSameScan(
	const mrpt::obs::CObservation2DRangeScan& a,
	const mrpt::obs::CObservation2DRangeScan& b)
{
	ASSERT_EQ(a.getScanSize(), b.getScanSize());
	for (size_t i = 0; i < a.getScanSize(); i++)
	{
		EXPECT_EQ(a.getScanRange(i), b.getScanRange(i));
		EXPECT_EQ(a.getScanRangeValidity(i), b.getScanRangeValidity(i));
	}
	EXPECT_EQ(a.sensorPose, b.sensorPose);
	EXPECT_EQ(a.timestamp, b.timestamp);
}

void expectSameStereo(
	const mrpt::obs::CObservationStereoImages& a,
	const mrpt::obs::CObservationStereoImages& b)
{
	EXPECT_TRUE(sameImage(a.imageLeft, b.imageLeft));
	EXPECT_TRUE(sameImage(a.imageRight, b.imageRight));
	EXPECT_TRUE(b.hasImageRight);
	EXPECT_EQ(a.leftCamera.intrinsicParams, b.leftCamera.intrinsicParams);
	EXPECT_EQ(a.leftCamera.dist, b.leftCamera.dist);
	EXPECT_EQ(a.rightCameraPose, b.rightCameraPose);
	EXPECT_EQ(a.cameraPose, b.cameraPose);
	EXPECT_EQ(a.timestamp, b.timestamp);
}

class RawlogRoundTrip : public ::testing::TestWithParam<RawlogFormat>
{
};

}  // namespace

TEST_P(RawlogRoundTrip, ObservationsReadBackUnchanged)
{
	const auto frames = simulate(5, 3);
	const std::string path =
		(std::filesystem::temp_directory_path() /
		 ("lvf_roundtrip_" + std::to_string(int(GetParam())) + "_" + std::to_string(::getpid()) + ".rawlog"))
			.string();
	{
		lvf::common::RawlogWriter writer(path, GetParam());
		for (const auto& f : frames)
			writer.append({f.timestamp, f.odometry, {f.scan, f.stereo}});
	}
	EXPECT_GE(gzipMembers(path), 2) << "three frames of 0.6 MB: more than a member's megabyte";
	mrpt::obs::CRawlog log;
	ASSERT_TRUE(log.loadFromRawLogFile(path));
	std::filesystem::remove(path);

	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> scans;
	std::vector<mrpt::obs::CObservationStereoImages::Ptr> stereo;
	std::vector<mrpt::poses::CPose2D> odometry;	 // obs: readings; sf: increments
	for (size_t i = 0; i < log.size(); i++)
	{
		switch (log.getType(i))
		{
			case mrpt::obs::CRawlog::etSensoryFrame:
				for (const auto& o : *log.getAsObservations(i))
				{
					if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) scans.push_back(s);
					if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(o)) stereo.push_back(s);
				}
				break;
			case mrpt::obs::CRawlog::etActionCollection:
			{
				auto move = log.getAsAction(i)->getBestMovementEstimation();
				ASSERT_TRUE(move);
				odometry.push_back(move->rawOdometryIncrementReading);
				break;
			}
			case mrpt::obs::CRawlog::etObservation:
			{
				auto o = log.getAsObservation(i);
				if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) scans.push_back(s);
				if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(o)) stereo.push_back(s);
				if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o)) odometry.push_back(s->odometry);
				break;
			}
			default:
				FAIL() << "unexpected entry " << i;
		}
	}
	ASSERT_EQ(scans.size(), frames.size());
	ASSERT_EQ(stereo.size(), frames.size());
	ASSERT_EQ(odometry.size(), frames.size());
	for (size_t k = 0; k < frames.size(); k++)
	{
		EXPECT_EQ(scans[k]->sensorLabel, "LASER");
		EXPECT_EQ(stereo[k]->sensorLabel, "STEREO");
		expectSameScan(*frames[k].scan, *scans[k]);
		expectSameStereo(*frames[k].stereo, *stereo[k]);
		const auto expected = GetParam() == RawlogFormat::Observations
			? frames[k].odometry
			: (k == 0 ? mrpt::poses::CPose2D() : frames[k].odometry - frames[k - 1].odometry);
		EXPECT_NEAR(odometry[k].x(), expected.x(), 1e-9);
		EXPECT_NEAR(odometry[k].y(), expected.y(), 1e-9);
		EXPECT_NEAR(odometry[k].phi(), expected.phi(), 1e-9);
	}
}

INSTANTIATE_TEST_SUITE_P(
	BothLayouts, RawlogRoundTrip,
	::testing::Values(RawlogFormat::ActionsSensoryFrames, RawlogFormat::Observations),
	[](const auto& info) {
		return info.param == RawlogFormat::Observations ? "Observations" : "ActionsSensoryFrames";
	});

TEST(Determinism, SameSeedSameBitsOtherSeedOtherNoise)
{
	const auto a = simulate(42, 2), b = simulate(42, 2), c = simulate(43, 2);
	for (size_t k = 0; k < a.size(); k++)
	{
		expectSameScan(*a[k].scan, *b[k].scan);
		expectSameStereo(*a[k].stereo, *b[k].stereo);
		EXPECT_EQ(a[k].odometry, b[k].odometry);
		EXPECT_FALSE(sameImage(a[k].stereo->imageLeft, c[k].stereo->imageLeft));
		EXPECT_NE(a[k].scan->getScanRange(90), c[k].scan->getScanRange(90));
	}
	// Ground truth does not depend on the noise seed.
	EXPECT_EQ(a[1].truthScan, c[1].truthScan);
	EXPECT_EQ(a[1].truePose, c[1].truePose);
}

// A write that fails (here /dev/full, a disk with no room) is one
// InputError naming the file, not MRPT's archive exception with its stack.
TEST(RawlogWriterErrors, AFullDiskIsReportedNamingTheFile)
{
	if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
	const auto frames = simulate(5, 2);
	lvf::common::RawlogWriter writer("/dev/full", RawlogFormat::Observations);
	try
	{
		// Images are far larger than gzip's buffer: they reach the device.
		for (const auto& f : frames) writer.append({f.timestamp, f.odometry, {f.scan, f.stereo}});
		writer.close();
		FAIL() << "writing to /dev/full succeeded";
	}
	catch (const lvf::common::InputError& e)
	{
		EXPECT_NE(std::string(e.what()).find("/dev/full"), std::string::npos) << e.what();
	}
}
