#include <lvfusion/navigation/NavigationOutcome.h>
#include <mrpt/core/format.h>

#include <cmath>

namespace lvf::navigation
{
const char* outcomeName(Outcome o)
{
	switch (o)
	{
		case Outcome::Reached: return "reached";
		case Outcome::Collision: return "collision";
		case Outcome::Timeout: return "timeout";
		case Outcome::NavigatorError: return "navigator-error";
		case Outcome::Unreachable: return "unreachable";
		case Outcome::StartInCollision: return "start-in-collision";
		case Outcome::TargetInObstacle: return "target-in-obstacle";
		case Outcome::InvalidPose: return "invalid-pose";
	}
	return "?";
}

int outcomeExitStatus(Outcome o)
{
	switch (o)
	{
		case Outcome::Reached: return 0;
		case Outcome::Collision:
		case Outcome::Timeout:
		case Outcome::NavigatorError:
		case Outcome::Unreachable: return 3;
		default: return 4;
	}
}

std::string NavigationMetrics::summary() const
{
	// A figure that has none (a run that never started: nan, inf) without
	// a unit after it.
	auto metres = [](double v, const char* format) {
		return std::isfinite(v) ? mrpt::format(format, v) + "m" : mrpt::format("%g", v);
	};
	return mrpt::format(
		"outcome=%s reached=%d collisions=%d time=%.1fs path=%.3fm final_distance=%s min_clearance=%s cycle=%.1fms",
		outcomeName(outcome), reached() ? 1 : 0, collisions, time, pathLength, metres(finalDistance, "%.2f").c_str(),
		metres(minClearance, "%.3f").c_str(), meanCycleMs);
}

double stepLengthInsideCircle(
	const mrpt::math::TPoint2D& from, const mrpt::math::TPoint2D& to,
	const mrpt::math::TPoint2D& centre, double radius)
{
	const mrpt::math::TPoint2D u = to - from, w = from - centre;
	const double uu = u.sqrNorm(), wu = w.x * u.x + w.y * u.y, ww = w.sqrNorm() - radius * radius;
	if (ww <= 0) return std::sqrt(uu);
	// |w + t u| = radius: the smaller root is where the step enters.
	const double disc = wu * wu - uu * ww;
	if (uu == 0 || disc < 0) return 0;
	const double enter = (-wu - std::sqrt(disc)) / uu;
	return enter < 0 || enter > 1 ? 0 : (1 - enter) * std::sqrt(uu);
}

}  // namespace lvf::navigation
