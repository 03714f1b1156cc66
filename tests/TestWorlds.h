#pragma once
// Small worlds and noise-free sensor settings shared by the tests.

#include <lvfusion/model/PlanarSceneModel.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/WorldLoader.h>

#include <string>

namespace lvf::test
{
/** Sensors with every noise source off, so geometry can be checked exactly. */
inline lvf::simulation::CStereoLaserSimulator::TOptions noiseFreeOptions()
{
	lvf::simulation::CStereoLaserSimulator::TOptions o;
	o.laser.noiseStd = 0;
	o.stereo.leftNoiseStd = o.stereo.rightNoiseStd = 0;
	o.odometry.xyStdPerMetre = o.odometry.yawStdPerRadian =
		o.odometry.yawStdPerMetre = 0;
	return o;
}

inline lvf::simulation::World worldFromText(const std::string& yaml)
{
	return lvf::simulation::parseWorld(yaml, "<test world>");
}

/** Robot at the origin looking along +x; a wall whose near face is the plane
 * x = wallX, 10 m wide, 3 m high. */
inline std::string wallWorld(double wallX, const std::string& texture = "noise")
{
	const double centre = wallX + 0.05;	 // walls are 0.1 m thick
	return "name: wall\n"
		   "walls:\n"
		   "  - {from: [" + std::to_string(centre) + ", 5], to: [" +
		std::to_string(centre) + ", -5], height: 3, texture: " + texture +
		"}\n"
		"path: {poses: [[0, 0, 0]]}\n";
}

/** A 6 x 6 m room (walls 0.1 m thick, inner faces at x = -1, 5, y = -3, 3)
 * around a robot at the origin looking along +x, plus `boxes`, YAML list
 * items ("  - {pose: ...}\n"), and `more` world keys ("tables:\n  - ...\n"). */
inline std::string roomWorld(const std::string& boxes, const std::string& more = "")
{
	return "name: room\n"
		   "walls:\n"
		   "  - {from: [-1.05, -3.05], to: [5.05, -3.05]}\n"
		   "  - {from: [5.05, -3.05], to: [5.05, 3.05]}\n"
		   "  - {from: [5.05, 3.05], to: [-1.05, 3.05]}\n"
		   "  - {from: [-1.05, 3.05], to: [-1.05, -3.05]}\n"
		   "boxes:" + (boxes.empty() ? std::string(" []\n") : "\n" + boxes) + more +
		"path: {poses: [[0, 0, 0]]}\n";
}

/** The model a perfect laser would give in roomWorld(): its inner faces. */
inline lvf::model::PlanarSceneModel roomModel()
{
	return lvf::model::PlanarSceneModel(
		{{{-1, -3}, {5, -3}}, {{5, -3}, {5, 3}}, {{5, 3}, {-1, 3}}, {{-1, 3}, {-1, -3}}});
}

}  // namespace lvf::test
