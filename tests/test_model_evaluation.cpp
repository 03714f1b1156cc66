// Stage 3 on simulated stereo with ground-truth depth: rectification puts
// known points where the rectified geometry says, and the NCC evaluation
// flags exactly the pixels where the laser's model is wrong.

#include "TestWorlds.h"

#include <gtest/gtest.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/OpenCvCamera.h>
#include <lvfusion/evaluation/GridWindowSums.h>
#include <lvfusion/evaluation/ModelDisparity.h>
#include <lvfusion/evaluation/ModelEvaluator.h>
#include <lvfusion/evaluation/ModelWarp.h>
#include <mrpt/core/bits_math.h>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include <cstring>

using namespace lvf::evaluation;
using lvf::simulation::CStereoLaserSimulator;
using lvf::simulation::World;

namespace
{
struct Scene
{
	CStereoLaserSimulator::Frame frame;
	RectifiedStereo stereo;
	cv::Mat1b left, right;
	ModelEvaluation eval;
};

/** Simulates the world (YAML) and evaluates the room's exact model on it. */
Scene evaluate(const std::string& worldYaml)
{
	Scene s;
	CStereoLaserSimulator sim(lvf::test::worldFromText(worldYaml), CStereoLaserSimulator::TOptions());
	s.frame = sim.simulateNextFrame(true);
	s.stereo.prepare(*s.frame.stereo, "frame 0");
	s.stereo.rectify(*s.frame.stereo, s.left, s.right);
	s.eval = ModelEvaluator().evaluate(
		s.left, s.right, renderModelDisparity(lvf::test::roomModel(), s.stereo.geometry()),
		s.stereo.geometry());
	return s;
}

/** Pixels where the model depth is wrong by more than 5 cm + 5 %, and where
 * it is right, both shrunk by the NCC window so no window straddles both. */
void truthMasks(const Scene& s, cv::Mat1b& modelWrong, cv::Mat1b& modelRight)
{
	const double fB = s.stereo.geometry().fB();
	modelWrong = cv::Mat1b::zeros(s.left.size());
	modelRight = cv::Mat1b::zeros(s.left.size());
	for (int v = 0; v < s.left.rows; v++)
		for (int u = 0; u < s.left.cols; u++)
		{
			const float d = s.eval.modelDisparity(v, u);
			const float zTrue = s.frame.leftDepth(v, u);
			if (d <= 0 || !std::isfinite(zTrue)) continue;
			const double zModel = fB / d;
			(std::abs(zTrue - zModel) > 0.05 + 0.05 * zModel ? modelWrong : modelRight)(v, u) = 255;
		}
	const cv::Mat kernel = cv::Mat::ones(11, 11, CV_8U);
	cv::erode(modelWrong, modelWrong, kernel);
	cv::erode(modelRight, modelRight, kernel);
}

/** Fraction of the mask's verifiable pixels in `state`; with `texturedOnly`
 * of its judged pixels (verifiable and textured). */
double fraction(
	const Scene& s, const cv::Mat1b& mask, PixelState state, size_t* judged = nullptr,
	bool texturedOnly = true)
{
	size_t n = 0, k = 0;
	for (int v = 0; v < mask.rows; v++)
		for (int u = 0; u < mask.cols; u++)
		{
			const auto st = static_cast<PixelState>(s.eval.state(v, u));
			if (!mask(v, u) || st == PixelState::Unverifiable) continue;
			if (!texturedOnly || st != PixelState::Untextured || state == PixelState::Untextured) n++;
			k += st == state;
		}
	if (judged) *judged = n;
	return n ? double(k) / double(n) : 0.0;
}

}  // namespace

TEST(RectifiedStereo, ParallelUndistortedRigIsUsedAsIs)
{
	CStereoLaserSimulator sim(lvf::test::worldFromText(lvf::test::roomWorld("")), CStereoLaserSimulator::TOptions());
	const auto f = sim.simulateNextFrame(false);
	RectifiedStereo stereo;
	stereo.prepare(*f.stereo, "frame 0");
	EXPECT_FALSE(stereo.remaps());
	const auto& g = stereo.geometry();
	EXPECT_DOUBLE_EQ(g.f, 450);
	EXPECT_DOUBLE_EQ(g.cx, 319.5);
	EXPECT_DOUBLE_EQ(g.cxOffset, 0);
	EXPECT_NEAR(g.baseline, 0.12, 1e-12);
	EXPECT_EQ(g.leftPose, mrpt::poses::CPose3D(f.stereo->cameraPose));
}

namespace
{
/** A checkerboard wall 2.5 m ahead of a toed-in, rolled rig with lens
 * distortion `dist` (SimulatedStereoRig's), rendered noise-free. */
CStereoLaserSimulator::Frame distortedMisalignedRigFrame(const std::vector<double>& dist)
{
	World world = lvf::test::worldFromText(lvf::test::wallWorld(
		2.5, "{kind: checker, scale: 0.25, albedo: 0.5, contrast: 0.4}"));
	auto opt = lvf::test::noiseFreeOptions();
	opt.stereo.poseX = opt.stereo.poseY = 0;
	opt.stereo.poseZ = 1.5;
	opt.stereo.tiltDeg = 0;
	opt.stereo.dist = dist;
	opt.stereo.rightYawDeg = -1.5;	// toed in
	opt.stereo.rightPitchDeg = 0.6;
	opt.stereo.rightRollDeg = 0.8;
	opt.stereo.supersampling = 3;
	CStereoLaserSimulator sim(world, opt);
	return sim.simulateNextFrame(false);
}

/** The wall's checker corners (every 0.25 m) found in the rectified pair
 * where the rectified geometry puts them: on one row, at their disparity. */
void expectCornersOnOneRowAtTheirDisparity(const CStereoLaserSimulator::Frame& f)
{
	RectifiedStereo stereo;
	stereo.prepare(*f.stereo, "frame 0");
	ASSERT_TRUE(stereo.remaps());
	cv::Mat1b left, right;
	stereo.rectify(*f.stereo, left, right);
	const auto& g = stereo.geometry();

	size_t corners = 0;
	double worstRow = 0, worstDisparity = 0, sumRow = 0;
	for (int k = -6; k <= 6; k++)
		for (int m = -4; m <= 4; m++)
		{
			const auto p = g.leftPose.inverseComposePoint({2.5, k * 0.25, 1.5 + m * 0.25});
			const cv::Point2f expectedL(
				static_cast<float>(g.f * p.x / p.z + g.cx), static_cast<float>(g.f * p.y / p.z + g.cy));
			const cv::Point2f expectedR(
				static_cast<float>(expectedL.x - g.fB() / p.z + g.cxOffset), expectedL.y);
			if (std::min({expectedL.x, expectedR.x, expectedL.y}) < 15 ||
				std::max(expectedL.x, expectedR.x) > g.size.width - 16 || expectedL.y > g.size.height - 16)
				continue;
			std::vector<cv::Point2f> l{expectedL + cv::Point2f(1.2f, -1.2f)}, r{expectedR + cv::Point2f(-1.2f, 1.2f)};
			const cv::TermCriteria stop(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 100, 1e-4);
			cv::cornerSubPix(left, l, cv::Size(5, 5), cv::Size(-1, -1), stop);
			cv::cornerSubPix(right, r, cv::Size(5, 5), cv::Size(-1, -1), stop);
			EXPECT_LT(cv::norm(l[0] - expectedL), 0.5) << k << "," << m;
			EXPECT_LT(std::abs(l[0].y - r[0].y), 0.6) << "rows differ at " << k << "," << m;
			EXPECT_LT(std::abs((l[0].x - r[0].x) - (expectedL.x - expectedR.x)), 0.5);
			worstRow = std::max(worstRow, double(std::abs(l[0].y - r[0].y)));
			sumRow += l[0].y - r[0].y;
			worstDisparity = std::max(
				worstDisparity, double(std::abs((l[0].x - r[0].x) - (expectedL.x - expectedR.x))));
			corners++;
		}
	EXPECT_GT(corners, 40u);
	// Corner localisation in resampled images adds its own error; on average
	// the rows must agree far better than the 0.6 px bound per corner.
	EXPECT_LT(std::abs(sumRow / corners), 0.1);
	std::cout << corners << " corners; mean row difference " << sumRow / corners
			  << " px; worst row difference " << worstRow
			  << " px, worst disparity error " << worstDisparity << " px\n";
}
}  // namespace

TEST(RectifiedStereo, DistortedMisalignedRigPutsKnownPointsOnOneRowAtTheirDisparity)
{
	expectCornersOnOneRowAtTheirDisparity(distortedMisalignedRigFrame({-0.2, 0.05, 0.001, -0.001, 0}));
}

// With alpha 1 the rectified pair keeps every pixel the cameras imaged, and
// corners no camera saw are black: RectificationEffects marks them, and the
// evaluation judges no window that touches one (a black corner's edge is
// texture). With alpha 0 nothing is outside.
TEST(RectifiedStereo, BlackCornersAreMarkedAndLeftUnjudged)
{
	const auto f = distortedMisalignedRigFrame({-0.2, 0.05, 0.001, -0.001, 0});
	RectifiedStereo cropped(0.0), whole(1.0);
	cropped.prepare(*f.stereo, "frame 0");
	whole.prepare(*f.stereo, "frame 0");
	cv::Mat1b left, right;
	const auto effects = whole.rectify(*f.stereo, left, right);
	ASSERT_FALSE(effects.leftNotImaged.empty());
	ASSERT_FALSE(effects.rightNotImaged.empty());
	const int area = left.rows * left.cols;
	EXPECT_GT(cv::countNonZero(effects.leftNotImaged), area / 100) << "alpha 1 shows the lens's black corners";
	// Marked pixels are black but for the corners' edges, where the
	// interpolation reads inside and outside (the wall's texture is never 0).
	for (const auto& [image, marks] : {std::pair{left, effects.leftNotImaged}, {right, effects.rightNotImaged}})
		EXPECT_LT(cv::countNonZero(marks & (image > 0)), cv::countNonZero(marks) / 20);
	cv::Mat1b croppedLeft, croppedRight;
	const auto croppedEffects = cropped.rectify(*f.stereo, croppedLeft, croppedRight);
	EXPECT_LT(croppedEffects.leftNotImaged.empty() ? 0 : cv::countNonZero(croppedEffects.leftNotImaged), area / 1000);

	// The wall 2.5 m ahead as the model; every judged window clear of the
	// marks, in the left image and where the model takes it in the right.
	const auto& g = whole.geometry();
	const cv::Mat1f modelDisparity(left.size(), float(g.fB() / 2.5));
	const int window = ModelEvaluator::TOptions().windowSize, half = window / 2;
	const auto eval = ModelEvaluator().evaluateGrid(left, right, modelDisparity, g, half, 3, effects);
	cv::Mat1b nearLeftMark;
	cv::dilate(effects.leftNotImaged, nearLeftMark, cv::Mat::ones(window, window, CV_8U));
	size_t judged = 0, touching = 0;
	for (int v = 0; v < left.rows; v++)
		for (int u = 0; u < left.cols; u++)
		{
			const auto s = static_cast<PixelState>(eval.state(v, u));
			if (s != PixelState::Consistent && s != PixelState::Inconsistent && s != PixelState::Unmodelled) continue;
			judged++;
			touching += nearLeftMark(v, u) > 0;
		}
	EXPECT_GT(judged, 1000u);
	EXPECT_EQ(touching, 0u);
	EXPECT_GT(eval.count(PixelState::Unverifiable), 100u);
}

TEST(RectifiedStereo, RationalDistortionModelIsUndoneWithAllEightCoefficients)
{
	// plumb_bob with k4-k6 (OpenCV's rational model): a 1 + 0.1 r^2 + 0.02
	// r^4 denominator moves the image's corners by several pixels.
	const std::vector<double> dist{-0.2, 0.05, 0.001, -0.001, 0, 0.1, 0.02, 0};
	const auto f = distortedMisalignedRigFrame(dist);
	// The renderer distorts with all eight: a corner of the wall, projected
	// here by OpenCV from the test's own numbers, is where the raw left
	// image shows it, and 5 coefficients alone would put it elsewhere.
	const auto& cam = f.stereo->leftCamera;
	const cv::Matx33d K(cam.fx(), 0, cam.cx(), 0, cam.fy(), cam.cy(), 0, 0, 1);
	const auto p = mrpt::poses::CPose3D(f.stereo->cameraPose).inverseComposePoint({2.5, 1.25, 1.5 + 0.75});
	std::vector<cv::Point2d> all8, first5;
	const std::vector<cv::Point3d> corner{{p.x, p.y, p.z}};
	cv::projectPoints(corner, cv::Vec3d::all(0), cv::Vec3d::all(0), K, dist, all8);
	cv::projectPoints(corner, cv::Vec3d::all(0), cv::Vec3d::all(0), K,
		std::vector<double>(dist.begin(), dist.begin() + 5), first5);
	ASSERT_GT(cv::norm(all8[0] - first5[0]), 3.0);
	std::vector<cv::Point2f> found{cv::Point2f(all8[0]) + cv::Point2f(1.2f, -1.2f)};
	cv::cornerSubPix(toGrey(f.stereo->imageLeft), found, cv::Size(5, 5), cv::Size(-1, -1),
		cv::TermCriteria(cv::TermCriteria::EPS | cv::TermCriteria::COUNT, 100, 1e-4));
	EXPECT_LT(cv::norm(cv::Point2d(found[0]) - all8[0]), 0.5) << all8[0] << " " << found[0];
	// And rectification undoes all eight.
	expectCornersOnOneRowAtTheirDisparity(f);
}

TEST(OpenCvCamera, ReadsTheLensAsMrptsRectifierDoesWithTheRationalTerms)
{
	mrpt::img::TCamera cam;
	cam.setIntrinsicParamsFromValues(450, 451, 319.5, 239.5);
	EXPECT_EQ(lvf::common::openCvCameraMatrix(cam), cv::Matx33d(450, 0, 319.5, 0, 451, 239.5, 0, 0, 1));
	EXPECT_TRUE(lvf::common::openCvDistortion(cam).empty());
	EXPECT_FALSE(lvf::common::hasLensDistortion(cam));
	// setDistortionParamsVector leaves the model `none`; the numbers count.
	cam.setDistortionParamsVector(std::vector<double>{-0.2, 0.05, 0.001, -0.001, 0.01});
	EXPECT_EQ(lvf::common::openCvDistortion(cam), (std::vector<double>{-0.2, 0.05, 0.001, -0.001, 0.01}));
	cam.setDistortionPlumbBob(-0.2, 0.05, 0.001, -0.001);
	cam.k5(0.02);
	EXPECT_EQ(lvf::common::openCvDistortion(cam), (std::vector<double>{-0.2, 0.05, 0.001, -0.001, 0, 0, 0.02, 0}));
	cam.distortion = mrpt::img::DistortionModel::kannala_brandt;
	EXPECT_FALSE(lvf::common::isPinholeModel(cam));
	EXPECT_THROW(lvf::common::openCvDistortion(cam), std::invalid_argument);
}

// What a camera sees, and where: the image's border bounds the view, the
// lens places the pixel. Checked against the projections' own formulas.
TEST(OpenCvCamera, PixelsInViewFollowTheLensToTheImageBorder)
{
	mrpt::img::TCamera cam;
	cam.ncols = 640, cam.nrows = 480;
	cam.setIntrinsicParamsFromValues(450, 450, 319.5, 239.5);
	auto deg = [](double a) { return a * M_PI / 180; };
	// On the axis, a hundredth of a pixel inside the last column (639), half
	// a pixel beyond it, behind the camera, and 37 degrees to the side (a
	// pin-hole sees 35.4).
	auto atColumn = [](double u) { return cv::Point3d((u - 319.5) / 450 * 2, 0, 2); };
	const std::vector<cv::Point3d> points{{0, 0, 2}, atColumn(638.99), atColumn(639.5), {0, 0, -2},
		{std::sin(deg(37)), 0, std::cos(deg(37))}};
	const auto pinhole = lvf::common::pixelsInView(points, cam);
	ASSERT_TRUE(pinhole[0] && pinhole[1]);
	EXPECT_NEAR(pinhole[0]->x, 319.5, 1e-9);
	EXPECT_NEAR(pinhole[0]->y, 239.5, 1e-9);
	EXPECT_NEAR(pinhole[1]->x, 638.99, 1e-9);
	EXPECT_FALSE(pinhole[2]);
	EXPECT_FALSE(pinhole[3]);
	EXPECT_FALSE(pinhole[4]);
	// An equidistant fish-eye (kannala_brandt, all terms 0: r = f theta)
	// sees 37 degrees at 450 * 0.6458 px from the centre.
	cam.distortion = mrpt::img::DistortionModel::kannala_brandt;
	const auto fisheye = lvf::common::pixelsInView(points, cam);
	ASSERT_TRUE(fisheye[4]);
	EXPECT_NEAR(fisheye[4]->x, 319.5 + 450 * deg(37), 1e-6);
	EXPECT_NEAR(fisheye[4]->y, 239.5, 1e-6);
	EXPECT_FALSE(fisheye[3]);
	// A rational lens: the pixel is cv::projectPoints' with all eight terms.
	cam.distortion = mrpt::img::DistortionModel::plumb_bob;
	cam.dist = {-0.25, 0.08, 0.0005, -0.0004, -0.01, 0.05, 0.01, 0.002};
	const std::vector<cv::Point3d> corner{{0.55, 0.40, 1.0}};
	std::vector<cv::Point2d> expected;
	cv::projectPoints(corner, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cv::Mat(lvf::common::openCvCameraMatrix(cam)),
		std::vector<double>(cam.dist.begin(), cam.dist.end()), expected);
	const auto rational = lvf::common::pixelsInView(corner, cam);
	ASSERT_TRUE(rational[0]) << expected[0];
	EXPECT_NEAR(rational[0]->x, expected[0].x, 1e-9);
	EXPECT_NEAR(rational[0]->y, expected[0].y, 1e-9);
}

TEST(RectifiedStereo, FishEyeCalibrationIsRefusedByName)
{
	// kannala_brandt has no pin-hole form in OpenCV's stereoRectify; read as
	// plumb_bob it would rectify to nonsense.
	CStereoLaserSimulator sim(lvf::test::worldFromText(lvf::test::roomWorld("")), CStereoLaserSimulator::TOptions());
	const auto f = sim.simulateNextFrame(false);
	f.stereo->rightCamera.distortion = mrpt::img::DistortionModel::kannala_brandt;
	f.stereo->rightCamera.dist = {0.01, -0.002, 0, 0, 0.0005, 0.0001, 0, 0};
	RectifiedStereo stereo;
	try
	{
		stereo.prepare(*f.stereo, "log.rawlog: frame 4");
		FAIL() << "a fish-eye calibration was accepted";
	}
	catch (const lvf::common::InputError& e)
	{
		EXPECT_EQ(std::string(e.what()),
			"log.rawlog: frame 4: right camera: fish-eye (kannala_brandt) distortion is not supported: give images "
			"rectified by cv::fisheye, or a plumb_bob calibration");
	}
}

TEST(ModelWarp, IsOpenCvsRemapAlongTheRowsBitForBit)
{
	// warpByModel does by hand what cv::remap does with maps x = u + cxOffset
	// - d, y = v, in 1/32 grey levels; the evaluation's NCC is computed from
	// it, so it must be 32 times remap's to the last bit. A simulated frame
	// with the room's model, and disparities of every kind: fractional, none
	// (0) or negative, sending the column past either edge of the image (the
	// vector path takes blocks of eight columns, the plain one those where a
	// column falls near or past an edge).
	const Scene scene = evaluate(lvf::test::roomWorld("  - {pose: [2.5, 0.3, 0.5], size: [0.4, 0.4, 0.4]}\n"));
	cv::RNG rng(3);
	cv::Mat1f odd(scene.right.size());
	rng.fill(odd, cv::RNG::UNIFORM, -3.0, scene.right.cols + 3.0);
	for (int v = 0; v < odd.rows; v += 7) odd.row(v).setTo(0);
	RectifiedGeometry shifted = scene.stereo.geometry();
	shifted.cxOffset = 12.3;  // as on a Middlebury pair (doffs)
	size_t compared = 0;
	for (const auto& [disparity, geometry] :
		 {std::pair{scene.eval.modelDisparity, scene.stereo.geometry()}, std::pair{odd, shifted}})
	{
		cv::Mat1w warped, warpedMarked;
		cv::Mat1b unverifiable, unverifiableMarked;
		warpByModel(scene.right, disparity, geometry, warped, unverifiable);
		// Columns rectification filled from outside the camera's image make
		// the pixels sampling next to them unverifiable too, nothing else.
		cv::Mat1b filled(scene.right.size());
		rng.fill(filled, cv::RNG::UNIFORM, 0, 2);
		filled *= 255;
		warpByModel(scene.right, disparity, geometry, warpedMarked, unverifiableMarked, filled);
		ASSERT_EQ(std::memcmp(warped.data, warpedMarked.data, warped.total() * sizeof(uint16_t)), 0);
		cv::Mat1f mapX(disparity.size()), mapY(disparity.size()), rightF, expected;
		for (int v = 0; v < mapX.rows; v++)
			for (int u = 0; u < mapX.cols; u++)
			{
				mapX(v, u) = static_cast<float>(u) - disparity(v, u) + static_cast<float>(geometry.cxOffset);
				mapY(v, u) = static_cast<float>(v);
			}
		scene.right.convertTo(rightF, CV_32F);
		cv::remap(rightF, expected, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, 0);
		for (int v = 0; v < mapX.rows; v++)
			for (int u = 0; u < mapX.cols; u++, compared++)
			{
				// remap's values are whole multiples of 1/32 (so exact times 32).
				ASSERT_EQ(float(warped(v, u)), expected(v, u) * 32.f)
					<< "row " << v << " column " << u << " (x " << mapX(v, u) << "): " << warped(v, u) << " vs 32 x " << expected(v, u);
				const bool outside = disparity(v, u) <= 0 || mapX(v, u) < 0 || mapX(v, u) > mapX.cols - 1;
				ASSERT_EQ(unverifiable(v, u) != 0, outside) << "row " << v << " column " << u;
				const int column = static_cast<int>(mapX(v, u));
				const bool nextToFilled =
					!outside && (filled(v, column) || filled(v, std::min(column + 1, filled.cols - 1)));
				ASSERT_EQ(unverifiableMarked(v, u) != 0, outside || nextToFilled) << "row " << v << " column " << u;
			}
	}
	EXPECT_EQ(compared, 2 * scene.right.total());
}

TEST(GridWindowSums, AreTheExactWindowSumsOfTheWarpedPair)
{
	// The grid evaluation's NCC comes from these integer sums; they stand in
	// for integral images in double, which were exact, so they must be the
	// true sums exactly. A simulated frame warped by its model and
	// by random disparities (columns past the edges: unverifiable pixels),
	// windows of every size the evaluation accepts, rows visited in steps
	// that slide the sums and steps that start them afresh.
	const Scene scene = evaluate(lvf::test::roomWorld("  - {pose: [2.5, 0.3, 0.5], size: [0.4, 0.4, 0.4]}\n"));
	cv::RNG rng(5);
	cv::Mat1f odd(scene.right.size());
	rng.fill(odd, cv::RNG::UNIFORM, -3.0, scene.right.cols + 3.0);
	size_t compared = 0;
	for (const cv::Mat1f& disparity : {scene.eval.modelDisparity, odd})
	{
		cv::Mat1w warped;
		cv::Mat1b unverifiable;
		warpByModel(scene.right, disparity, scene.stereo.geometry(), warped, unverifiable);
		for (int half : {1, 2, 5, 7, 15})
		{
			GridWindowSums sums(scene.left, warped, unverifiable, half);
			std::vector<int> rows;
			for (int v = half, step = 1; v < warped.rows - half; v += step, step = step % 41 + 3) rows.push_back(v);
			rows.push_back(half + 2);  // backwards: afresh
			for (int v : rows)
			{
				sums.moveTo(v);
				for (int u = half; u < warped.cols - half; u += 37, compared++)
				{
					// Summed pixel by pixel, in the sums' own units: the warp's
					// values are 32 x the grey level already.
					double l = 0, ll = 0, w32 = 0, ww1024 = 0, lw32 = 0, bad = 0;
					for (int dv = -half; dv <= half; dv++)
						for (int du = -half; du <= half; du++)
						{
							const double a = scene.left(v + dv, u + du), b32 = warped(v + dv, u + du);
							l += a, ll += a * a, w32 += b32, ww1024 += b32 * b32, lw32 += a * b32;
							bad += unverifiable(v + dv, u + du) != 0;
						}
					const GridWindowSums::Sums got = sums.at(u);
					SCOPED_TRACE(testing::Message() << "half " << half << " at (" << u << ", " << v << ")");
					ASSERT_EQ(double(got.l), l);
					ASSERT_EQ(double(got.ll), ll);
					ASSERT_EQ(double(got.w32), w32);
					ASSERT_EQ(double(got.ww1024), ww1024);
					ASSERT_EQ(double(got.lw32), lw32);
					ASSERT_EQ(double(got.unverifiable), bad);
				}
			}
		}
	}
	EXPECT_GT(compared, 4000u);
	{
		// White images and the largest window: the running sums along a row
		// pass 2^32 many times over (they are kept modulo 2^32), and L W's
		// window sum comes within 7 % of 2^31.
		const cv::Mat1b white(120, 640, uint8_t{255});
		const cv::Mat1w whiteWarped(white.size(), 255 * 32);
		const cv::Mat1b none = cv::Mat1b::zeros(white.size());
		const int half = 15;
		GridWindowSums sums(white, whiteWarped, none, half);
		const int64_t area = (2 * half + 1) * (2 * half + 1);
		for (int v : {half, half + 3, white.rows - 1 - half})
		{
			sums.moveTo(v);
			for (int u : {half, 300, white.cols - 1 - half})
			{
				const GridWindowSums::Sums got = sums.at(u);
				ASSERT_EQ(got.l, area * 255);
				ASSERT_EQ(got.ll, area * 255 * 255);
				ASSERT_EQ(got.w32, area * 255 * 32);
				ASSERT_EQ(got.ww1024, area * 255 * 255 * 1024);
				ASSERT_EQ(got.lw32, area * 255 * 255 * 32);
				ASSERT_EQ(got.unverifiable, 0);
			}
		}
	}
	// 33 rows of W^2 would overflow the 32-bit column sums: refused.
	cv::Mat1w warped;
	cv::Mat1b unverifiable;
	warpByModel(scene.right, scene.eval.modelDisparity, scene.stereo.geometry(), warped, unverifiable);
	EXPECT_THROW(GridWindowSums(scene.left, warped, unverifiable, 16), std::invalid_argument);
}

TEST(ModelEvaluation, FlagsTheFloatingBoxAndNothingElse)
{
	// A textured box floating at 0.5..0.9 m, 2 m ahead: not in the model.
	const Scene s = evaluate(lvf::test::roomWorld("  - {pose: [2.0, 0.2, 0], size: [0.5, 0.6, 0.4], elevation: 0.5}\n"));
	cv::Mat1b wrong, right;
	truthMasks(s, wrong, right);
	size_t nWrong = 0, nRight = 0;
	const double detected = fraction(s, wrong, PixelState::Inconsistent, &nWrong);
	const double falseAlarms = fraction(s, right, PixelState::Inconsistent, &nRight);
	std::cout << "inconsistent: " << detected * 100 << " % of " << nWrong
			  << " model-wrong pixels, " << falseAlarms * 100 << " % of " << nRight
			  << " model-right pixels\n";
	EXPECT_GT(nWrong, 3000u);
	EXPECT_GT(nRight, 100000u);
	// Misses: where the box's texture, shifted by the model's wrong
	// disparity, still resembles itself. False alarms: wall pixels the box
	// occludes in the right image (the model is right, the views differ).
	EXPECT_GT(detected, 0.93);
	EXPECT_LT(falseAlarms, 0.015);
}

TEST(ModelEvaluation, UntexturedSurfacesAreNotJudged)
{
	// The far wall (in the model) and a floating box (not in it) have no
	// texture: neither may be called inconsistent for lack of evidence. The
	// box's face edges are real evidence, so only its faces' interiors count.
	std::string yaml = lvf::test::roomWorld(
		"  - {pose: [2.0, 0.2, 0], size: [0.5, 0.6, 0.4], elevation: 0.5, texture: none}\n");
	yaml.replace(yaml.find("to: [5.05, 3.05]}"), 17, "to: [5.05, 3.05], texture: none}");
	const Scene s = evaluate(yaml);
	cv::Mat1b wrong, right, flat;
	truthMasks(s, wrong, right);
	// Interiors of flat regions: no edge within the NCC window.
	cv::Mat1b edges;
	cv::Canny(s.left, edges, 20, 40);
	cv::dilate(edges, edges, cv::Mat::ones(13, 13, CV_8U));
	cv::bitwise_not(edges, flat);
	cv::Mat1b flatWrong = wrong & flat, flatRight = right & flat;
	size_t nBox = 0, nWall = 0;
	const double boxUntextured = fraction(s, flatWrong, PixelState::Untextured);
	const double boxInconsistent = fraction(s, flatWrong, PixelState::Inconsistent, &nBox, false);
	const double wallInconsistent = fraction(s, flatRight, PixelState::Inconsistent, &nWall, false);
	std::cout << "textureless box interior: " << boxUntextured * 100 << " % untextured, "
			  << boxInconsistent * 100 << " % inconsistent; model-right flat pixels: "
			  << wallInconsistent * 100 << " % inconsistent\n";
	EXPECT_GT(nBox, 2000u);
	EXPECT_GT(nWall, 20000u);
	EXPECT_GT(boxUntextured, 0.95);
	EXPECT_LT(boxInconsistent, 0.02);
	EXPECT_LT(wallInconsistent, 0.01);
}

TEST(ModelEvaluation, GridEvaluationJudgesItsPixelsLikeTheWholeImage)
{
	// The floating box scene: the grid evaluation must reproduce the whole
	// image's judgement at its pixels (only rounding differs: exact window
	// sums against float box filters) and still flag the box.
	const Scene s = evaluate(lvf::test::roomWorld("  - {pose: [2.0, 0.2, 0], size: [0.5, 0.6, 0.4], elevation: 0.5}\n"));
	const int half = 5, stride = 3;
	const ModelEvaluation grid = ModelEvaluator().evaluateGrid(
		s.left, s.right, s.eval.modelDisparity, s.stereo.geometry(), half, stride);
	cv::Mat1b wrong, right;
	truthMasks(s, wrong, right);
	size_t onGrid = 0, sameState = 0, wrongOnGrid = 0, wrongFlagged = 0, offGridEvaluated = 0;
	double worstNcc = 0, worstStd = 0;
	for (int v = 0; v < s.left.rows; v++)
		for (int u = 0; u < s.left.cols; u++)
		{
			const bool gridPixel = v >= half && u >= half && v < s.left.rows - half &&
				u < s.left.cols - half && (v - half) % stride == 0 && (u - half) % stride == 0;
			const auto st = static_cast<PixelState>(grid.state(v, u));
			if (!gridPixel)
			{
				offGridEvaluated += st != PixelState::NotEvaluated;
				continue;
			}
			onGrid++;
			sameState += grid.state(v, u) == s.eval.state(v, u);
			worstStd = std::max(worstStd, double(std::abs(grid.leftStd(v, u) - s.eval.leftStd(v, u))));
			if (st != PixelState::Unverifiable && st != PixelState::Untextured)
				worstNcc = std::max(worstNcc, double(std::abs(grid.ncc(v, u) - s.eval.ncc(v, u))));
			if (wrong(v, u) && st != PixelState::Unverifiable && st != PixelState::Untextured)
			{
				wrongOnGrid++;
				wrongFlagged += st == PixelState::Inconsistent;
			}
		}
	std::cout << onGrid << " grid pixels, " << onGrid - sameState << " judged differently; worst NCC difference "
			  << worstNcc << ", worst std difference " << worstStd << " grey levels; "
			  << wrongFlagged << " of " << wrongOnGrid << " model-wrong grid pixels flagged\n";
	EXPECT_EQ(offGridEvaluated, 0u);
	EXPECT_EQ(grid.count(PixelState::NotEvaluated), size_t(s.left.total()) - onGrid);
	EXPECT_GT(onGrid, 30000u);
	EXPECT_GE(double(sameState) / double(onGrid), 0.999);
	EXPECT_LT(worstNcc, 1e-3);
	EXPECT_LT(worstStd, 1e-2);
	EXPECT_GT(wrongOnGrid, 300u);
	EXPECT_GT(double(wrongFlagged) / double(wrongOnGrid), 0.93);
}
