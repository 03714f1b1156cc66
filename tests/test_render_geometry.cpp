// The stereo renderer against analytic geometry: depth of known planes,
// checkerboard corners against MRPT's own projection with distortion, and the
// culling renderer against brute force.

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <lvfusion/simulation/WorldGeometry.h>
#include <lvfusion/simulation/WorldLoader.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/vision/pinhole.h>
#include <opencv2/imgproc.hpp>

#include <cmath>

using namespace lvf::simulation;

namespace
{
SimulatedStereoRig::TOptions levelRig()
{
	auto o = lvf::test::noiseFreeOptions().stereo;
	o.poseX = 0;
	o.poseY = 0;
	o.poseZ = 1.0;
	o.tiltDeg = 0;
	return o;
}
}  // namespace

TEST(RenderGeometry, LevelCameraDepthIsTheAnalyticFloorOrWall)
{
	const World world = lvf::test::worldFromText(lvf::test::wallWorld(4.0));
	const WorldGeometry geometry(world);
	const auto opt = levelRig();
	const SimulatedStereoRig rig(opt);
	const auto images = rig.render(geometry, mrpt::poses::CPose3D(), 1, true);

	// Camera at height H looking along +x: pixel (u, v) sees the wall at depth
	// 4 unless its ray meets the floor first, at depth H * fy / (v - cy).
	const double H = opt.poseZ;
	const double kNothing = std::numeric_limits<double>::infinity();
	size_t floorPixels = 0, wallPixels = 0;
	for (int v = 0; v < opt.nrows; v++)
		for (int u = 0; u < opt.ncols; u++)
		{
			const double yn = (v - opt.cy) / opt.fy;
			// The wall spans heights 0..3 m; above it the ray sees nothing.
			double expected = H - 4.0 * yn <= 3.0 ? 4.0 : kNothing;
			if (yn > 0 && H / yn < expected) expected = H / yn;
			if (expected == kNothing)
			{
				ASSERT_TRUE(std::isinf(images.leftDepth(v, u))) << "pixel " << u << "," << v;
				continue;
			}
			(expected < 4.0 ? floorPixels : wallPixels)++;
			ASSERT_NEAR(images.leftDepth(v, u), expected, 1e-4 * expected)
				<< "pixel " << u << "," << v;
		}
	EXPECT_GT(floorPixels, 10000u);
	EXPECT_GT(wallPixels, 10000u);
	// One pixel by hand: row 400 is (400 - 239.5) / 450 below the axis.
	EXPECT_NEAR(images.leftDepth(400, 320), 1.0 / (160.5 / 450.0), 1e-4);
}

TEST(RenderGeometry, TiltedPannedCameraDepthMatchesThePlaneThroughMrptPoses)
{
	const World world = lvf::test::worldFromText(lvf::test::wallWorld(3.0));
	const WorldGeometry geometry(world);
	auto opt = levelRig();
	opt.tiltDeg = 20;
	opt.panDeg = 10;
	opt.poseX = 0.2;
	opt.poseY = 0.1;
	const SimulatedStereoRig rig(opt);
	const mrpt::poses::CPose3D robot(0.3, -0.2, 0, mrpt::DEG2RAD(5.0), 0, 0);
	const auto images = rig.render(geometry, robot, 1, true);
	const mrpt::poses::CPose3D camera = robot + opt.leftCameraPose();

	size_t checked = 0;
	for (int v = 0; v < opt.nrows; v += 7)
		for (int u = 0; u < opt.ncols; u += 7)
		{
			// The pixel's ray in the world, intersected with z = 0 and x = 3.
			double dx, dy, dz;
			camera.composePoint(
				(u - opt.cx) / opt.fx, (v - opt.cy) / opt.fy, 1.0, dx, dy, dz);
			dx -= camera.x();
			dy -= camera.y();
			dz -= camera.z();
			double expected = (3.0 - camera.x()) / dx;	// depth = ray parameter
			if (dz < 0) expected = std::min(expected, -camera.z() / dz);
			ASSERT_NEAR(images.leftDepth(v, u), expected, 1e-4 * expected)
				<< "pixel " << u << "," << v;
			checked++;
		}
	EXPECT_GT(checked, 5000u);
}

TEST(RenderGeometry, CheckerCornersLandWhereMrptProjectsThemWithDistortion)
{
	// A checkerboard wall at x = 2.5 seen through a distorted lens by both
	// cameras; every square corner is a known 3D point.
	const double scale = 0.25, wallX = 2.5;
	const World world = lvf::test::worldFromText(lvf::test::wallWorld(
		wallX, "{kind: checker, scale: 0.25, albedo: 0.5, contrast: 0.4}"));
	const WorldGeometry geometry(world);
	auto opt = levelRig();
	opt.dist = {-0.25, 0.08, 0.001, -0.0015, 0.0};
	opt.supersampling = 5;	// anti-aliased edges, so corners are sub-pixel
	const SimulatedStereoRig rig(opt);
	const auto images = rig.render(geometry, mrpt::poses::CPose3D(), 1, false);
	const auto calib = opt.stereoCamera();
	const mrpt::poses::CPose3D left = opt.leftCameraPose();
	const mrpt::poses::CPose3D right =
		left + opt.rightCameraPose();

	size_t corners = 0;
	double worst = 0;
	for (const auto& [image, pose, cam] :
		 {std::tuple{images.left, left, calib.leftCamera},
		  std::tuple{images.right, right, calib.rightCamera}})
		for (int k = -8; k <= 8; k++)
			for (int m = -5; m <= 5; m++)
			{
				// Wall centre height is 1.5 m; corners every `scale` from there.
				const mrpt::math::TPoint3D world3D(wallX, k * scale, 1.5 + m * scale);
				const auto p = pose.inverseComposePoint(world3D);
				mrpt::img::TPixelCoordf expected;
				mrpt::vision::pinhole::projectPoint_with_distortion(p, cam, expected);
				if (expected.x < 12 || expected.y < 12 ||
					expected.x > cam.ncols - 13 || expected.y > cam.nrows - 13)
					continue;
				// Start the search 1.5 px away so the detector has to find it.
				std::vector<cv::Point2f> found{
					{expected.x + 1.5f, expected.y - 1.5f}};
				cv::cornerSubPix(
					image, found, cv::Size(5, 5), cv::Size(-1, -1),
					cv::TermCriteria(
						cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 100, 1e-4));
				const double err =
					std::hypot(found[0].x - expected.x, found[0].y - expected.y);
				worst = std::max(worst, err);
				EXPECT_LT(err, 0.5) << "corner " << k << "," << m << " at "
									<< expected.x << "," << expected.y;
				corners++;
			}
	EXPECT_GT(corners, 100u);
	RecordProperty("worst_corner_error_px", std::to_string(worst));
	std::cout << "worst corner error: " << worst << " px over " << corners
			  << " corners\n";
}

TEST(RenderGeometry, TileCullingGivesExactlyTheBruteForceImage)
{
	const World world = loadWorldFile(std::string(LVF_SHARE_DIR) + "/worlds/box_room.yaml");
	const WorldGeometry geometry(world);
	const auto opt = lvf::test::noiseFreeOptions().stereo;
	const SimulatedStereoRig rig(opt);
	for (const auto& pose : {world.path.front(), world.path.back()})
	{
		const mrpt::poses::CPose3D camera =
			mrpt::poses::CPose3D(mrpt::poses::CPose2D(pose)) + opt.leftCameraPose();
		cv::Mat1b culled, brute;
		cv::Mat1f culledDepth, bruteDepth;
		rig.renderCamera(geometry, camera, rig.leftRays(), 1, 0, 1, culled, &culledDepth, false);
		rig.renderCamera(geometry, camera, rig.leftRays(), 1, 0, 1, brute, &bruteDepth, true);
		EXPECT_EQ(cv::countNonZero(culled != brute), 0);
		EXPECT_EQ(cv::countNonZero(culledDepth != bruteDepth), 0);
	}
}
