#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/simulation/SimulatedStereoRig.h>
#include <mrpt/core/bits_math.h>
#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>

#include <cmath>

namespace lvf::simulation
{
using lvf::common::writeOption;

void SimulatedStereoRig::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	ncols = ini.integer("ncols", ncols, 16, 8192);
	nrows = ini.integer("nrows", nrows, 16, 8192);
	fx = ini.real("fx", fx, 1e-3);
	fy = ini.real("fy", fy, 1e-3);
	cx = ini.real("cx", cx);
	cy = ini.real("cy", cy);
	dist = ini.reals("dist", dist);
	if (dist.size() != 5 && dist.size() != 8)
		throw lvf::common::InputError(
			ini.sourceName(), "[" + section + "] dist",
			"needs 5 values [k1 k2 p1 p2 k3] or 8 [k1 k2 p1 p2 k3 k4 k5 k6], got " +
				std::to_string(dist.size()));
	baseline = ini.real("baseline", baseline, 1e-3, 10);
	rightYawDeg = ini.real("right_yaw_deg", rightYawDeg, -20, 20);
	rightPitchDeg = ini.real("right_pitch_deg", rightPitchDeg, -20, 20);
	rightRollDeg = ini.real("right_roll_deg", rightRollDeg, -20, 20);
	poseX = ini.real("pose_x", poseX);
	poseY = ini.real("pose_y", poseY);
	poseZ = ini.real("pose_z", poseZ, 1e-3);
	panDeg = ini.real("pan_deg", panDeg, -180, 180);
	tiltDeg = ini.real("tilt_deg", tiltDeg, -89, 89);
	leftGain = ini.real("left_gain", leftGain, 0, 10);
	rightGain = ini.real("right_gain", rightGain, 0, 10);
	leftNoiseStd = ini.real("left_noise_std", leftNoiseStd, 0, 255);
	rightNoiseStd = ini.real("right_noise_std", rightNoiseStd, 0, 255);
	supersampling = ini.integer("supersampling", supersampling, 1, 7);
	if (supersampling % 2 == 0)
		throw lvf::common::InputError(
			ini.sourceName(), "[" + section + "] supersampling",
			"must be odd (1, 3, 5 or 7) so a sample falls on each pixel centre");
	ini.rejectUnknownKeys();
}

void SimulatedStereoRig::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "ncols", ncols, "image width [px]");
	writeOption(c, s, "nrows", nrows, "image height [px]");
	writeOption(c, s, "fx", fx, "focal length along x [px]");
	writeOption(c, s, "fy", fy, "focal length along y [px]");
	writeOption(c, s, "cx", cx, "principal point x [px] (pixel centres are integers)");
	writeOption(c, s, "cy", cy, "principal point y [px]");
	writeOption(c, s, "dist", dist, "plumb_bob distortion [k1 k2 p1 p2 k3], or with [k4 k5 k6] (OpenCV's rational model); zeros: none");
	writeOption(c, s, "baseline", baseline, "right camera offset along the left camera's x [m]");
	writeOption(c, s, "right_yaw_deg", rightYawDeg, "right camera rotation vs the left, yaw (0: parallel rig) [deg]");
	writeOption(c, s, "right_pitch_deg", rightPitchDeg, "right camera rotation vs the left, pitch [deg]");
	writeOption(c, s, "right_roll_deg", rightRollDeg, "right camera rotation vs the left, roll [deg]");
	writeOption(c, s, "pose_x", poseX, "left camera position on the robot, forward [m]");
	writeOption(c, s, "pose_y", poseY, "left camera position on the robot, left [m]");
	writeOption(c, s, "pose_z", poseZ, "left camera height above the floor [m]");
	writeOption(c, s, "pan_deg", panDeg, "camera heading, left positive [deg]");
	writeOption(c, s, "tilt_deg", tiltDeg, "camera tilt, looking down positive [deg]");
	writeOption(c, s, "left_gain", leftGain, "left camera intensity gain");
	writeOption(c, s, "right_gain", rightGain, "right camera intensity gain");
	writeOption(c, s, "left_noise_std", leftNoiseStd, "left image Gaussian noise [grey levels]");
	writeOption(c, s, "right_noise_std", rightNoiseStd, "right image Gaussian noise [grey levels]");
	writeOption(c, s, "supersampling", supersampling, "samples per pixel per axis, odd (anti-aliasing; 3 or more for a rig that needs rectifying: its resampled images alias unlike a parallel pair's, README)");
}

mrpt::img::TStereoCamera SimulatedStereoRig::TOptions::stereoCamera() const
{
	mrpt::img::TCamera cam;
	cam.ncols = static_cast<uint32_t>(ncols);
	cam.nrows = static_cast<uint32_t>(nrows);
	cam.setIntrinsicParamsFromValues(fx, fy, cx, cy);
	if (std::any_of(dist.begin(), dist.end(), [](double d) { return d != 0; }))
	{
		cam.setDistortionPlumbBob(dist[0], dist[1], dist[2], dist[3], dist[4]);
		if (dist.size() == 8) cam.k4(dist[5]), cam.k5(dist[6]), cam.k6(dist[7]);
	}
	mrpt::img::TStereoCamera stereo;
	stereo.leftCamera = cam;
	stereo.rightCamera = cam;
	stereo.rightCameraPose =
		mrpt::math::TPose3DQuat(mrpt::poses::CPose3DQuat(rightCameraPose()).asTPose());
	return stereo;
}

mrpt::poses::CPose3D SimulatedStereoRig::TOptions::rightCameraPose() const
{
	return mrpt::poses::CPose3D(
		baseline, 0, 0, mrpt::DEG2RAD(rightYawDeg), mrpt::DEG2RAD(rightPitchDeg),
		mrpt::DEG2RAD(rightRollDeg));
}

mrpt::poses::CPose3D SimulatedStereoRig::TOptions::leftCameraPose() const
{
	// A level camera looking along the robot's x axis is
	// CPose3D(x, y, z, -90deg, 0, -90deg) (DESIGN.md); panning adds to the
	// yaw, tilting down rotates about the camera's own x axis, i.e. the roll.
	return mrpt::poses::CPose3D(
		poseX, poseY, poseZ, mrpt::DEG2RAD(panDeg - 90.0), 0,
		mrpt::DEG2RAD(-90.0 - tiltDeg));
}

SimulatedStereoRig::SimulatedStereoRig(const TOptions& options)
	: m_options(options), m_calibration(options.stereoCamera())
{
	m_leftRays = std::make_unique<CameraRayTable>(
		m_calibration.leftCamera, options.supersampling);
	m_rightRays = std::make_unique<CameraRayTable>(
		m_calibration.rightCamera, options.supersampling);
}

SimulatedStereoRig::Images SimulatedStereoRig::render(
	const WorldGeometry& world, const mrpt::poses::CPose3D& robotPose,
	uint64_t noiseSeed, bool withDepth) const
{
	Images out;
	const mrpt::poses::CPose3D left = robotPose + m_options.leftCameraPose();
	const mrpt::poses::CPose3D right = left + m_options.rightCameraPose();
	// Two independent renders, each with its own noise seed: side by side
	// on OpenCV's threads (one after the other on one thread), the same
	// images either way.
	cv::parallel_for_(cv::Range(0, 2), [&](const cv::Range& cameras) {
		for (int k = cameras.start; k < cameras.end; k++)
			if (k == 0)
				renderCamera(
					world, left, *m_leftRays, m_options.leftGain, m_options.leftNoiseStd,
					2 * noiseSeed, out.left, withDepth ? &out.leftDepth : nullptr);
			else
				renderCamera(
					world, right, *m_rightRays, m_options.rightGain,
					m_options.rightNoiseStd, 2 * noiseSeed + 1, out.right, nullptr);
	});
	return out;
}

mrpt::obs::CObservationStereoImages::Ptr SimulatedStereoRig::toObservation(
	const Images& images, mrpt::Clock::time_point stamp) const
{
	auto obs = std::make_shared<mrpt::obs::CObservationStereoImages>();
	obs->sensorLabel = "STEREO";
	obs->timestamp = stamp;
	obs->imageLeft = mrpt::img::CImage(images.left, mrpt::img::DEEP_COPY);
	obs->imageRight = mrpt::img::CImage(images.right, mrpt::img::DEEP_COPY);
	obs->hasImageRight = true;
	obs->setStereoCameraParams(m_calibration);
	obs->cameraPose = mrpt::poses::CPose3DQuat(m_options.leftCameraPose());
	return obs;
}

}  // namespace lvf::simulation
