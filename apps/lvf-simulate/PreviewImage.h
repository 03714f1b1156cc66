#pragma once
// A picture of what the laser misses: the left image of a frame with the
// laser's returns drawn in green and, at every hidden bearing, the truth
// obstacle column (robot height band) drawn in red.

#include <lvfusion/simulation/CStereoLaserSimulator.h>

#include <string>

namespace lvf::apps
{
void writePreviewImage(
	const std::string& path,
	const lvf::simulation::CStereoLaserSimulator::Frame& frame,
	const std::vector<bool>& hidden, const lvf::simulation::RobotBody& robot);
}
