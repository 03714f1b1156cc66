#pragma once
// Small worlds and noise-free sensor settings shared by the tests.

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

}  // namespace lvf::test
