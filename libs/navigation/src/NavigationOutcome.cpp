#include <lvfusion/navigation/NavigationOutcome.h>
#include <mrpt/core/format.h>

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
	return mrpt::format(
		"outcome=%s reached=%d collisions=%d time=%.1fs path=%.2fm final_distance=%.2fm "
		"min_clearance=%.3fm cycle=%.1fms",
		outcomeName(outcome), reached() ? 1 : 0, collisions, time, pathLength, finalDistance,
		minClearance, meanCycleMs);
}

}  // namespace lvf::navigation
