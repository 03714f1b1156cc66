// The simulated laser and the truth scan against hand-computed ranges.

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <lvfusion/metrics/ScanMetrics.h>
#include <lvfusion/simulation/GroundTruth.h>
#include <lvfusion/simulation/SimulatedOdometry.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

using namespace lvf::simulation;

TEST(SimulatedLaser, RangeToAKnownWallIsExactWithoutNoise)
{
	// Wall face at x = 4, 10 m wide; the laser sits 0.15 m ahead of the robot
	// centre, so along bearing b it measures (4 - 0.15) / cos(b) where the
	// ray meets the wall (|y| <= 5) within the maximum range.
	const World world = lvf::test::worldFromText(lvf::test::wallWorld(4.0));
	const WorldGeometry geometry(world);
	auto opt = lvf::test::noiseFreeOptions().laser;
	const SimulatedLaser laser(opt);
	const auto scan = laser.scan(geometry, mrpt::poses::CPose3D(), 1, {});
	ASSERT_EQ(scan->getScanSize(), 181u);
	for (size_t i = 0; i < scan->getScanSize(); i++)
	{
		const double b = scan->getScanAngle(i);
		const double expected = (4.0 - opt.poseX) / std::cos(b);
		const bool reachable = std::abs(b) < M_PI_2 - 1e-9 && expected < opt.maxRange &&
			std::abs((4.0 - opt.poseX) * std::tan(b)) <= 5.0;
		ASSERT_EQ(scan->getScanRangeValidity(i), reachable) << "ray " << i;
		if (reachable)
		{
			EXPECT_NEAR(scan->getScanRange(i), expected, 1e-5) << "ray " << i;
		}
	}
	EXPECT_NEAR(scan->getScanRange(90), 3.85, 1e-5);  // straight ahead
}

TEST(SimulatedLaser, NoiseHasTheConfiguredStandardDeviation)
{
	const World world = lvf::test::worldFromText(lvf::test::wallWorld(3.0));
	const WorldGeometry geometry(world);
	SimulatedLaser::TOptions opt;  // default: 5 cm
	const SimulatedLaser laser(opt);
	double sum = 0, sumSq = 0;
	size_t n = 0;
	for (uint64_t seed = 0; seed < 20; seed++)
	{
		const auto scan = laser.scan(geometry, mrpt::poses::CPose3D(), seed, {});
		for (size_t i = 30; i <= 150; i++)	// bearings within +-60 deg
		{
			const double e = scan->getScanRange(i) -
				(3.0 - opt.poseX) / std::cos(scan->getScanAngle(i));
			sum += e;
			sumSq += e * e;
			n++;
		}
	}
	const double mean = sum / n, stddev = std::sqrt(sumSq / n - mean * mean);
	EXPECT_NEAR(mean, 0.0, 0.005);
	EXPECT_NEAR(stddev, opt.noiseStd, 0.1 * opt.noiseStd);
}

// Each step's reading errs by the configured spread, in position and in
// heading, and the three errors are independent: a heading that never
// drifted made every localisation test pass on dead reckoning alone.
TEST(SimulatedOdometry, EachStepsNoiseHasTheConfiguredStandardDeviations)
{
	SimulatedOdometry::TOptions opt;  // defaults: 0.02 m/m, 0.03 rad/rad, 0.01 rad/m
	const double stepLength = 0.5, stepTurn = 0.2;
	double sumX = 0, sumY = 0, sumYaw = 0, sumXYaw = 0;
	size_t n = 0;
	for (uint64_t seed = 0; seed < 20; seed++)
	{
		SimulatedOdometry odometry(opt, seed);
		mrpt::poses::CPose2D truth(1, 2, 0.3), reading = odometry.update(truth);
		for (int k = 0; k < 100; k++, n++)
		{
			const mrpt::poses::CPose2D step(stepLength, 0, stepTurn);
			truth = truth + step;
			const mrpt::poses::CPose2D next = odometry.update(truth);
			// The step as read (in the frame of the last reading), against the
			// step as driven.
			const mrpt::poses::CPose2D read = next - reading;
			reading = next;
			const double ex = read.x() - step.x(), ey = read.y() - step.y();
			const double eyaw = mrpt::math::wrapToPi(read.phi() - step.phi());
			sumX += ex * ex, sumY += ey * ey, sumYaw += eyaw * eyaw, sumXYaw += ex * eyaw;
		}
	}
	const double xyStd = opt.xyStdPerMetre * stepLength;
	const double yawStd = opt.yawStdPerRadian * stepTurn + opt.yawStdPerMetre * stepLength;
	EXPECT_NEAR(std::sqrt(sumX / n), xyStd, 0.1 * xyStd);
	EXPECT_NEAR(std::sqrt(sumY / n), xyStd, 0.1 * xyStd);
	EXPECT_NEAR(std::sqrt(sumYaw / n), yawStd, 0.1 * yawStd);
	EXPECT_LT(std::abs(sumXYaw / n) / (xyStd * yawStd), 0.15) << "position and heading noise correlated";
}

TEST(TruthScan, MatchesHandComputedRangesAndIgnoresBoxesOutsideTheBand)
{
	// A box whose near face is at x = 1.5 and spans y in [-0.5, 0.5], floating
	// at 0.5..1.0 m: inside the band [0.05, 1.2], above the laser plane.
	// Two distractors: a box above the robot, and a flat mat below the band.
	const World world = lvf::test::worldFromText(
		"name: t\n"
		"boxes:\n"
		"  - {pose: [2, 0, 0], size: [1, 1, 0.5], elevation: 0.5}\n"
		"  - {pose: [0, 2, 0], size: [1, 1, 0.5], elevation: 1.3}\n"
		"  - {pose: [0, -2, 0], size: [1, 1, 0.03]}\n"
		"path: {poses: [[0, 0, 0]]}\n");
	const WorldGeometry geometry(world);
	const auto opt = lvf::test::noiseFreeOptions();
	const SimulatedLaser laser(opt.laser);
	const mrpt::poses::CPose3D robot;
	const auto scan = laser.scan(geometry, robot, 1, {});
	const auto truth = truthScan(world, robot, *scan);

	const double nearFace = 1.5 - opt.laser.poseX;	// 1.35 m from the laser
	for (size_t i = 0; i < truth.size(); i++)
	{
		const double b = scan->getScanAngle(i);
		const bool hitsBox = std::abs(nearFace * std::tan(b)) <= 0.5 && std::abs(b) < M_PI_2;
		if (hitsBox)
			EXPECT_NEAR(truth[i], nearFace / std::cos(b), 1e-5) << "bearing " << b;
		else
			EXPECT_TRUE(std::isinf(truth[i])) << "bearing " << b << " " << truth[i];
	}
	EXPECT_NEAR(truth[90], 1.35, 1e-6);
	// The laser passes under the floating box: nothing at all ahead.
	EXPECT_FALSE(scan->getScanRangeValidity(90));

	// So bearing 0 is "hidden" in the DESIGN.md sense, if the camera sees it.
	const SimulatedStereoRig rig(opt.stereo);
	const auto stereo = rig.toObservation(
		rig.render(geometry, robot, 1, false), mrpt::Clock::time_point());
	const auto inView = lvf::metrics::bearingsInView(
		*scan, truth, *stereo, {world.robot.obstacleMinHeight, world.robot.height}, 8.0);
	const auto hidden = lvf::metrics::hiddenBearings(*scan, truth, inView);
	EXPECT_TRUE(inView[90]);
	EXPECT_TRUE(hidden[90]);
	EXPECT_FALSE(inView[0]);  // straight to the right: outside a 70 deg camera
}

TEST(ObstacleGrid, OccupiesExactlyTheCellsUnderBandBoxes)
{
	const World world = lvf::test::worldFromText(
		"name: g\n"
		"boxes:\n"
		"  - {pose: [1.0, 1.0, 0], size: [0.4, 0.2, 1]}\n"
		"  - {pose: [3.0, 1.0, 45], size: [0.5, 0.5, 0.3], elevation: 2.0}\n"
		"path: {poses: [[0, 0, 0]]}\n");
	const auto grid = obstacleGrid(world, 0.05, 0.5);
	size_t occupied = 0;
	for (unsigned cy = 0; cy < grid.getSizeY(); cy++)
		for (unsigned cx = 0; cx < grid.getSizeX(); cx++)
			if (grid.getCell(cx, cy) < 0.5f)
			{
				occupied++;
				EXPECT_NEAR(grid.idx2x(cx), 1.0, 0.2 + 0.025 + 1e-6);
				EXPECT_NEAR(grid.idx2y(cy), 1.0, 0.1 + 0.025 + 1e-6);
			}
	// 0.4 x 0.2 m at 5 cm cells: 8 x 4 cells if aligned, at most 10 x 6.
	EXPECT_GE(occupied, 8u * 4u);
	EXPECT_LE(occupied, 10u * 6u);
	EXPECT_GT(grid.getPos(3.0, 1.0), 0.5f);
}

namespace
{
/** A 181-ray scan over 180 degrees, 0.3 m up, every truth range `range`. */
mrpt::obs::CObservation2DRangeScan halfCircleScan()
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = float(M_PI);
	scan.rightToLeft = true;
	scan.resizeScan(181);
	for (size_t i = 0; i < 181; i++) scan.setScanRange(i, 8.f), scan.setScanRangeValidity(i, true);
	scan.sensorPose = mrpt::poses::CPose3D(0, 0, 0.3, 0, 0, 0);
	return scan;
}
}  // namespace

// Which bearings a camera with a barrel lens sees. A lens polynomial has a
// largest image radius: past it (k1 = -0.2: 52 degrees off the axis)
// projecting a point through it folds the point back towards the image, so
// projecting the scan's bearings (MRPT's projectPoint_with_distortion, as
// bearingsInView did) put bearings 57-68 degrees to the side in view of a
// camera that sees 41 degrees either way (measured with that version). The view is the image's border
// undistorted: the camera's own field of view, wider than the pin-hole's
// 35.4 degrees by what the lens bends in.
TEST(BearingsInView, ABarrelLensSeesWiderButNotItsFoldedBackSides)
{
	const auto scan = halfCircleScan();
	mrpt::obs::CObservationStereoImages stereo;
	stereo.cameraPose = mrpt::poses::CPose3DQuat(mrpt::poses::CPose3D(0, 0, 1.0, -M_PI_2, 0, -M_PI_2));
	auto& cam = stereo.leftCamera;
	cam.ncols = 640, cam.nrows = 480;
	cam.fx(450), cam.fy(450), cam.cx(319.5), cam.cy(239.5);
	cam.dist.fill(0);
	const std::vector<float> truth(181, 3.f);
	const lvf::HeightBand band{0.05, 1.2};
	const auto pinhole = lvf::metrics::bearingsInView(scan, truth, stereo, band, 8.0);
	cam.dist[0] = -0.2;
	const auto barrel = lvf::metrics::bearingsInView(scan, truth, stereo, band, 8.0);
	// Half the field of view: atan(319.5 / 450) = 35.4 degrees for the
	// pin-hole; with the lens, the ideal x where x - 0.2 x^3 = 319.5 / 450,
	// 0.826: 39.6 degrees on the image's middle row, and wider below it,
	// where the band's foot lies (0.95 m under the camera, 3 m out: to 41
	// degrees, by the lens model x_d = x (1 - 0.2 r^2) forward).
	for (size_t i = 0; i < 181; i++)
	{
		const double off = std::abs(int(i) - 90);	// degrees off the camera's axis
		if (off <= 34) { EXPECT_TRUE(pinhole[i]) << off; }
		if (off >= 37) { EXPECT_FALSE(pinhole[i]) << off; }
		if (off <= 41) { EXPECT_TRUE(barrel[i]) << off; }
		if (off >= 42) { EXPECT_FALSE(barrel[i]) << off; }
	}
}
