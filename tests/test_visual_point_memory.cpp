// VisualPointMemory against analytic geometry: a level camera 1 m up looking
// along the robot's +x, points placed where its view does or does not reach
// after the robot moves by exact odometry.

#include <gtest/gtest.h>
#include <lvfusion/fusion/VisualPointMemory.h>
#include <mrpt/core/bits_math.h>

#include <cmath>

using lvf::fusion::VisualPointMemory;

namespace
{
/** 640 x 480, f = 450 px (half-angles 35.4 deg across, 28.1 deg up and down). */
lvf::evaluation::RectifiedGeometry levelCamera()
{
	lvf::evaluation::RectifiedGeometry g;
	g.size = cv::Size(640, 480);
	g.f = 450;
	g.cx = 319.5;
	g.cy = 239.5;
	g.baseline = 0.12;
	// MRPT camera axes: z forward (robot +x), x right (robot -y), y down.
	g.leftPose = mrpt::poses::CPose3D(0, 0, 1.0, mrpt::DEG2RAD(-90.0), 0, mrpt::DEG2RAD(-90.0));
	return g;
}

/** The whole image but a 5 px border, depths 0.3-5 m, in both images. */
VisualPointMemory::SearchedView wholeImageView()
{
	VisualPointMemory::SearchedView v;
	v.firstColumn = v.firstRightColumn = v.firstRow = 5;
	v.lastColumn = v.lastRightColumn = 634;
	v.lastRow = 474;
	v.zMin = 0.3, v.zMax = 5.0;
	return v;
}
const VisualPointMemory::SearchedView kView = wholeImageView();

lvf::depth::VisualPoint at(double x, double y, double z)
{
	lvf::depth::VisualPoint p;
	p.robot = {x, y, z};
	return p;
}

VisualPointMemory memory(double maxTravel)
{
	VisualPointMemory::TOptions o;
	o.maxTravel = maxTravel;
	return VisualPointMemory(o);
}
}  // namespace

TEST(VisualPointMemory, KeepsWhatLeftTheViewWhereItIsAndDropsWhatIsStillInView)
{
	auto m = memory(2.0);
	const auto g = levelCamera();
	EXPECT_TRUE(m.recall(mrpt::poses::CPose2D(0, 0, 0), g, kView).empty());
	// Ahead (in view now and after), and 31 deg left at 1 m, which 0.5 m on
	// is 50 deg left: beyond the image's side.
	m.remember({at(2.0, 0, 0.5), at(1.0, 0.6, 0.5)});
	const auto kept = m.recall(mrpt::poses::CPose2D(0.5, 0, 0), g, kView);
	ASSERT_EQ(kept.size(), 1u);
	EXPECT_NEAR(kept[0].robot.x(), 0.5, 1e-12);
	EXPECT_NEAR(kept[0].robot.y(), 0.6, 1e-12);
	EXPECT_NEAR(kept[0].robot.z(), 0.5, 1e-12);
	EXPECT_TRUE(std::isnan(kept[0].u)) << "a remembered point has no pixel in this frame";
	EXPECT_EQ(m.size(), 1u) << "the point still in view is this frame's to find again";
}

TEST(VisualPointMemory, FollowsTheRobotRoundATurn)
{
	auto m = memory(2.0);
	const auto g = levelCamera();
	m.recall(mrpt::poses::CPose2D(1, 2, 0), g, kView);
	m.remember({at(2.0, 0, 0.5)});	// odometry frame (3, 2)
	// Turned 90 deg left where it stands: the point is now on its right.
	const auto kept = m.recall(mrpt::poses::CPose2D(1, 2, M_PI_2), g, kView);
	ASSERT_EQ(kept.size(), 1u);
	EXPECT_NEAR(kept[0].robot.x(), 0.0, 1e-12);
	EXPECT_NEAR(kept[0].robot.y(), -2.0, 1e-12);
	// Turned back: in view again, and gone though nothing was found there.
	EXPECT_TRUE(m.recall(mrpt::poses::CPose2D(1, 2, 0), g, kView).empty());
}

TEST(VisualPointMemory, KeepsWhatIsInTheImageButOutsideTheSearchedDepths)
{
	auto m = memory(2.0);
	const auto g = levelCamera();
	m.recall(mrpt::poses::CPose2D(0, 0, 0), g, kView);
	// 0.1 m down at 0.8 m, then 0.2 m in front of the camera: nearer than z_min.
	m.remember({at(0.8, 0, 0.9)});
	const auto kept = m.recall(mrpt::poses::CPose2D(0.6, 0, 0), g, kView);
	ASSERT_EQ(kept.size(), 1u);
	EXPECT_NEAR(kept[0].robot.x(), 0.2, 1e-12);
}

TEST(VisualPointMemory, ForgetsAfterTheTravelLimit)
{
	auto m = memory(1.0);
	const auto g = levelCamera();
	m.recall(mrpt::poses::CPose2D(0, 0, 0), g, kView);
	m.remember({at(1.0, 0.6, 0.5)});
	// Driven 0.5 + 0.4 m: kept; 0.3 m more (1.2 m): forgotten.
	EXPECT_EQ(m.recall(mrpt::poses::CPose2D(0.5, 0, 0), g, kView).size(), 1u);
	EXPECT_EQ(m.recall(mrpt::poses::CPose2D(0.9, 0, 0), g, kView).size(), 1u);
	EXPECT_TRUE(m.recall(mrpt::poses::CPose2D(1.2, 0, 0), g, kView).empty());
	EXPECT_EQ(m.size(), 0u);
}

TEST(VisualPointMemory, ANonFinitePoseEmptiesIt)
{
	auto m = memory(2.0);
	const auto g = levelCamera();
	m.recall(mrpt::poses::CPose2D(0, 0, 0), g, kView);
	m.remember({at(1.0, 0.6, 0.5)});
	EXPECT_TRUE(m.recall(mrpt::poses::CPose2D(std::nan(""), 0, 0), g, kView).empty());
	EXPECT_EQ(m.size(), 0u);
	m.remember({at(1.0, 0.6, 0.5)});
	EXPECT_EQ(m.size(), 0u) << "no pose to place them by";
}

TEST(VisualPointMemory, OffWithNoTravel)
{
	EXPECT_FALSE(memory(0).enabled());
	EXPECT_TRUE(memory(0.1).enabled());
}

TEST(VisualPointMemory, KeepsWhatTheRightCameraCannotMatch)
{
	auto m = memory(2.0);
	const auto g = levelCamera();
	m.recall(mrpt::poses::CPose2D(0, 0, 0), g, kView);
	// 0.5 m on, both 1 m ahead and 0.1 m below the camera (row 284.5,
	// disparity 450 * 0.12 / 1 = 54 px): 0.643 m left is the left image's
	// column 30.2, whose match would lie at -23.8, off the right image; 0.5
	// m left is column 94.5, matched at 40.5.
	m.remember({at(1.5, 0.643, 0.9), at(1.5, 0.5, 0.9)});
	const auto kept = m.recall(mrpt::poses::CPose2D(0.5, 0, 0), g, kView);
	ASSERT_EQ(kept.size(), 1u) << "the search could not have matched the first: it is still remembered";
	EXPECT_NEAR(kept[0].robot.y(), 0.643, 1e-12);
}

TEST(VisualPointMemory, KeepsWhatFallsOnPixelsNoCameraImaged)
{
	auto m = memory(2.0);
	const auto g = levelCamera();
	// Black corners of a rectified pair: the left image's bottom right, and
	// in the right image where the second point's match lies.
	auto view = kView;
	view.leftNotImaged = cv::Mat1b::zeros(g.size);
	view.rightNotImaged = cv::Mat1b::zeros(g.size);
	view.leftNotImaged(cv::Rect(440, 320, 30, 20)).setTo(255);  // holds (454.5, 329.5)
	view.rightNotImaged(cv::Rect(380, 270, 20, 30)).setTo(255);	 // holds (390.0, 284.5)
	m.recall(mrpt::poses::CPose2D(0, 0, 0), g, view);
	// 0.5 m on, each 1 m ahead (disparity 54 px): 0.3 m right and 0.2 m
	// below the camera is the left image's (454.5, 329.5), marked; 0.277 m
	// right, 0.1 m below is (444.0, 284.5), unmarked, matched at 390.0,
	// marked; 0.1 m right is (364.5, 284.5), matched at 310.5: neither.
	const double yMarkedRight = -(390.0 + 54.0 - 319.5) / 450.0;
	m.remember({at(1.5, -0.3, 0.8), at(1.5, yMarkedRight, 0.9), at(1.5, -0.1, 0.9)});
	const auto kept = m.recall(mrpt::poses::CPose2D(0.5, 0, 0), g, view);
	ASSERT_EQ(kept.size(), 2u) << "the unmarked third point was this frame's to find";
	EXPECT_NEAR(kept[0].robot.y(), -0.3, 1e-12);
	EXPECT_NEAR(kept[1].robot.y(), yMarkedRight, 1e-12);
}
