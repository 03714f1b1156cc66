// The path-length metric of a reached run: its last step counts only up to
// the target tolerance circle (NavigationOutcome.h). Analytic cases.

#include <gtest/gtest.h>
#include <lvfusion/navigation/NavigationOutcome.h>

#include <cmath>

using lvf::navigation::stepLengthInsideCircle;
using P = mrpt::math::TPoint2D;

TEST(StepLengthInsideCircle, StraightInIsTheDepthReached)
{
	// Radius 0.3 round the origin, a step along x from 1.0 to 0.2.
	EXPECT_NEAR(stepLengthInsideCircle(P(1.0, 0), P(0.2, 0), P(0, 0), 0.3), 0.1, 1e-12);
	// The same about another centre, from another side.
	EXPECT_NEAR(stepLengthInsideCircle(P(2, 4), P(2, 3.05), P(2, 2.8), 0.3), 0.05, 1e-12);
}

TEST(StepLengthInsideCircle, ObliqueStepFromItsEntryPoint)
{
	// y = 0.2 meets the circle at x = -sqrt(0.3^2 - 0.2^2).
	const double entry = -std::sqrt(0.09 - 0.04);
	EXPECT_NEAR(stepLengthInsideCircle(P(-1, 0.2), P(0.1, 0.2), P(0, 0), 0.3), 0.1 - entry, 1e-12);
}

TEST(StepLengthInsideCircle, NothingWhenTheStepStaysOutside)
{
	EXPECT_EQ(stepLengthInsideCircle(P(1, 0), P(0.5, 0), P(0, 0), 0.3), 0.0);
	// Heading away, and passing beside it.
	EXPECT_EQ(stepLengthInsideCircle(P(0.5, 0), P(1, 0), P(0, 0), 0.3), 0.0);
	EXPECT_EQ(stepLengthInsideCircle(P(-1, 0.5), P(1, 0.5), P(0, 0), 0.3), 0.0);
	// Standing still outside.
	EXPECT_EQ(stepLengthInsideCircle(P(1, 1), P(1, 1), P(0, 0), 0.3), 0.0);
}

TEST(StepLengthInsideCircle, AllOfAStepThatStartsInside)
{
	EXPECT_NEAR(stepLengthInsideCircle(P(0.1, 0), P(0, 0.1), P(0, 0), 0.3), std::sqrt(0.02), 1e-12);
}
