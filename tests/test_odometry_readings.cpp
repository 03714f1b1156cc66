// A scan's odometry pose, as lvf-fuse and lvf-map take it from a log's
// CObservationOdometry readings: the latest reading not after the scan (the
// first, for a scan before it), whatever order the readings come in the file.

#include <gtest/gtest.h>
#include <lvfusion/common/OdometryReadings.h>

#include <chrono>

using lvf::common::OdometryReadings;
using mrpt::poses::CPose2D;

namespace
{
mrpt::Clock::time_point at(double seconds) { return mrpt::Clock::fromDouble(1.7e9 + seconds); }
}  // namespace

TEST(OdometryReadings, GiveTheLatestReadingNotAfterATimeWhateverTheirOrderInTheFile)
{
	OdometryReadings readings;
	// As a log merged from two sources may hold them: out of time order.
	readings.add(at(0.2), CPose2D(2, 0, 0));
	readings.add(at(0.0), CPose2D(0, 0, 0));
	readings.add(at(0.4), CPose2D(4, 0, 0));
	readings.add(at(0.1), CPose2D(1, 0, 0));

	EXPECT_EQ(readings.earliest().x(), 0);
	EXPECT_EQ(readings.poseAt(at(-0.1)).x(), 0);  // before the first: the first
	EXPECT_EQ(readings.poseAt(at(0.0)).x(), 0);
	EXPECT_EQ(readings.poseAt(at(0.15)).x(), 1);
	EXPECT_EQ(readings.poseAt(at(0.2)).x(), 2);
	EXPECT_EQ(readings.poseAt(at(0.39)).x(), 2);
	EXPECT_EQ(readings.poseAt(at(10)).x(), 4);
}

TEST(OdometryReadings, TakeAReadingAMicrosecondLateAsTheScansAndTheLastOfEqualTimes)
{
	OdometryReadings readings;
	EXPECT_TRUE(readings.empty());
	const auto t = at(1.0);
	readings.add(t + std::chrono::microseconds(1), CPose2D(1, 0, 0));  // a scan's reading, rounded
	EXPECT_EQ(readings.poseAt(t).x(), 1);
	readings.add(t + std::chrono::microseconds(3), CPose2D(3, 0, 0));
	EXPECT_EQ(readings.poseAt(t).x(), 1);
	readings.add(t + std::chrono::microseconds(1), CPose2D(2, 0, 0));  // the same time again: the file's later
	EXPECT_EQ(readings.poseAt(t).x(), 2);
	EXPECT_FALSE(readings.empty());
}
