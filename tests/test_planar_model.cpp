// Stage 2: the planar model against analytic ray casts, and its rasterised
// disparity (stage 3's input) against per-pixel ray casting.

#include <gtest/gtest.h>
#include <lvfusion/evaluation/ModelDisparity.h>
#include <lvfusion/model/PlanarSceneModel.h>
#include <mrpt/core/bits_math.h>

#include <cmath>

using lvf::model::ModelHit;
using lvf::model::PlanarSceneModel;
using lvf::model::VerticalWall;

TEST(PlanarSceneModel, RayCastsMatchHandComputedHits)
{
	// A wall on x = 3 from y = -1 to y = 2, floor at z = 0.
	const PlanarSceneModel model({{{3, -1}, {3, 2}}}, 0.0);
	const Eigen::Vector3d eye(0, 0, 1);
	// Straight ahead, level: the wall at t = 3 (any height: unbounded).
	auto h = model.castRay(eye, {1, 0, 0});
	EXPECT_EQ(h.surface, 0);
	EXPECT_NEAR(h.t, 3.0, 1e-12);
	h = model.castRay(eye, {1, 0, 5});	// steeply up: still the wall
	EXPECT_EQ(h.surface, 0);
	EXPECT_NEAR(h.t, 3.0, 1e-12);
	// Down at 45 deg: the floor at 1 m comes first.
	h = model.castRay(eye, {1, 0, -1});
	EXPECT_EQ(h.surface, ModelHit::kFloor);
	EXPECT_NEAR(h.t, 1.0, 1e-12);
	// Past the wall's end (y = -1 at x = 3 means bearing atan(1/3)).
	h = model.castRay(eye, {1, -0.34, 0});
	EXPECT_FALSE(h.hit());
	h = model.castRay(eye, {1, -0.33, 0});
	EXPECT_EQ(h.surface, 0);
	EXPECT_NEAR(h.t, 3.0, 1e-12);
	// Parallel to the wall, and backwards: nothing.
	EXPECT_FALSE(model.castRay(eye, {0, 1, 0}).hit());
	EXPECT_FALSE(model.castRay(eye, {-1, 0, 0}).hit());
}

TEST(ModelDisparity, RasterisedDisparityEqualsPerPixelRayCasting)
{
	// A room corner, a free-standing segment and a tilted, panned, rolled
	// camera: the rasteriser must give exactly fB / depth of castRay.
	const PlanarSceneModel model(
		{{{4, -3}, {4, 3}}, {{0, 3}, {4, 3}}, {{2, -0.5}, {2.5, 0.3}}, {{1.5, -2}, {3, -1.5}}}, 0.0);
	lvf::evaluation::RectifiedGeometry g;
	g.size = cv::Size(320, 240);
	g.f = 250;
	g.cx = 160.3;
	g.cy = 119.7;
	g.baseline = 0.1;
	for (const auto& pose :
		 {mrpt::poses::CPose3D(0.1, 0.05, 1.0, mrpt::DEG2RAD(-90.0), 0, mrpt::DEG2RAD(-105.0)),
		  mrpt::poses::CPose3D(0.3, -0.2, 0.8, mrpt::DEG2RAD(-70.0), mrpt::DEG2RAD(4.0), mrpt::DEG2RAD(-95.0))})
	{
		g.leftPose = pose;
		const cv::Mat1f d = lvf::evaluation::renderModelDisparity(model, g);
		const Eigen::Matrix3d R = pose.getRotationMatrix().asEigen();
		const Eigen::Vector3d C(pose.x(), pose.y(), pose.z());
		size_t walls = 0, floor = 0;
		for (int v = 0; v < g.size.height; v++)
			for (int u = 0; u < g.size.width; u++)
			{
				const Eigen::Vector3d dir = R * Eigen::Vector3d(g.rayX(u), g.rayY(v), 1.0);
				const ModelHit hit = model.castRay(C, dir);
				const double expected = hit.hit() ? g.fB() / hit.t : 0.0;  // t is the depth
				ASSERT_NEAR(d(v, u), expected, 1e-4 * std::max(1.0, expected))
					<< "pixel " << u << "," << v << " surface " << hit.surface;
				(hit.surface == ModelHit::kFloor ? floor : walls)++;
			}
		EXPECT_GT(walls, 10000u);
		EXPECT_GT(floor, 10000u);
	}
}
