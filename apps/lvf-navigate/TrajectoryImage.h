#pragma once
// The run over the ground truth, like the paper's Figs. 8 and 13: the world's
// obstacles in the robot's height band (black), the cells the robot's own
// grid took as obstacles (dark red over a true obstacle, orange where there
// is none), its path (red), the last global plan (violet), start (green),
// target and tolerance (blue), and where it hit something (a red cross); a
// legend under it.

#include <lvfusion/navigation/NavigationRun.h>

#include <string>

namespace lvf::apps
{
void writeTrajectoryImage(
	const lvf::navigation::NavigationScenario& scenario, const lvf::navigation::NavigationRun& run,
	double targetTolerance, const std::string& path);
}
