#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/simulation/SimulatedLaser.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/core/format.h>
#include <opencv2/core.hpp>

#include <cmath>

namespace lvf::simulation
{
using lvf::common::writeOption;

void SimulatedLaser::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	apertureDeg = ini.real("aperture_deg", apertureDeg, 1, 360);
	resolutionDeg = ini.real("resolution_deg", resolutionDeg, 0.01, 90);
	// A scan's rays are spread over its aperture (MRPT's convention): one
	// ray would have no spacing.
	if (rayCount() < 2)
		throw lvf::common::InputError(
			ini.sourceName(), "[" + section + "] resolution_deg",
			mrpt::format("%g leaves a single ray in an aperture of %g deg: must be at most %g", resolutionDeg, apertureDeg,
						 2 * apertureDeg));
	maxRange = ini.real("max_range", maxRange, 0.1, 200);
	noiseStd = ini.real("noise_std", noiseStd, 0, 1);
	poseX = ini.real("pose_x", poseX);
	poseY = ini.real("pose_y", poseY);
	poseZ = ini.real("pose_z", poseZ, 1e-3);
	poseYawDeg = ini.real("pose_yaw_deg", poseYawDeg, -180, 180);
	ini.rejectUnknownKeys();
}

void SimulatedLaser::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "aperture_deg", apertureDeg, "field of view, centred on the sensor's x axis [deg]");
	writeOption(c, s, "resolution_deg", resolutionDeg, "angle between consecutive rays [deg]");
	writeOption(c, s, "max_range", maxRange, "no return beyond this range [m]");
	writeOption(c, s, "noise_std", noiseStd, "Gaussian range noise, standard deviation [m]");
	writeOption(c, s, "pose_x", poseX, "sensor position on the robot, forward [m]");
	writeOption(c, s, "pose_y", poseY, "sensor position on the robot, left [m]");
	writeOption(c, s, "pose_z", poseZ, "height of the scan plane above the floor [m]");
	writeOption(c, s, "pose_yaw_deg", poseYawDeg, "sensor heading on the robot [deg]");
}

size_t SimulatedLaser::TOptions::rayCount() const
{
	return static_cast<size_t>(std::lround(apertureDeg / resolutionDeg)) + 1;
}

mrpt::poses::CPose3D SimulatedLaser::TOptions::sensorPose() const
{
	return mrpt::poses::CPose3D(
		poseX, poseY, poseZ, mrpt::DEG2RAD(poseYawDeg), 0, 0);
}

mrpt::obs::CObservation2DRangeScan::Ptr SimulatedLaser::scan(
	const WorldGeometry& world, const mrpt::poses::CPose3D& robotPose,
	uint64_t noiseSeed, mrpt::Clock::time_point stamp) const
{
	auto obs = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
	obs->sensorLabel = "LASER";
	obs->timestamp = stamp;
	obs->aperture = static_cast<float>(mrpt::DEG2RAD(m_options.apertureDeg));
	obs->rightToLeft = true;
	obs->maxRange = static_cast<float>(m_options.maxRange);
	obs->stdError = static_cast<float>(m_options.noiseStd);
	obs->sensorPose = m_options.sensorPose();
	const size_t n = m_options.rayCount();
	obs->resizeScan(n);

	const mrpt::poses::CPose3D sensor = robotPose + obs->sensorPose;
	const Eigen::Vector3d origin(sensor.x(), sensor.y(), sensor.z());
	cv::RNG rng(noiseSeed ^ 0x1a5e7ULL);
	for (size_t i = 0; i < n; i++)
	{
		// MRPT's convention: ray i at -aperture/2 + i * aperture/(n-1).
		const double bearing = -0.5 * obs->aperture +
			obs->aperture * static_cast<double>(i) / static_cast<double>(n - 1);
		double dx, dy, dz;
		sensor.composePoint(std::cos(bearing), std::sin(bearing), 0, dx, dy, dz);
		const Eigen::Vector3d dir = Eigen::Vector3d(dx, dy, dz) - origin;
		const RayHit hit = world.castRay(origin, dir, m_options.maxRange);
		const double noise = rng.gaussian(m_options.noiseStd);
		const bool valid = hit.hit() && hit.t + noise < m_options.maxRange;
		obs->setScanRange(
			i, valid ? static_cast<float>(std::max(0.0, hit.t + noise))
					 : obs->maxRange);
		obs->setScanRangeValidity(i, valid);
	}
	return obs;
}

}  // namespace lvf::simulation
