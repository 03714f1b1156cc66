#pragma once
// A 2D scanning range finder (default: the paper's SICK PLS, 180 deg at
// 1 deg, 8 m, 5 cm noise) ray-cast against the same geometry as the cameras.

#include <lvfusion/simulation/WorldGeometry.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose3D.h>

namespace lvf::simulation
{
class SimulatedLaser
{
   public:
	/** INI section [SimulatedLaser]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		double apertureDeg = 180;  //!< field of view [deg]
		double resolutionDeg = 1;  //!< angle between rays [deg]
		double maxRange = 8.0;	//!< beyond this: no return [m]
		double noiseStd = 0.05;	 //!< Gaussian range noise [m]
		double poseX = 0.15, poseY = 0, poseZ = 0.30;  //!< on the robot [m]
		double poseYawDeg = 0;	//!< [deg]

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;

		size_t rayCount() const;
		mrpt::poses::CPose3D sensorPose() const;
	};

	explicit SimulatedLaser(const TOptions& options) : m_options(options) {}

	/** A scan (label LASER) with the robot at `robotPose`, world frame. */
	mrpt::obs::CObservation2DRangeScan::Ptr scan(
		const WorldGeometry& world, const mrpt::poses::CPose3D& robotPose,
		uint64_t noiseSeed, mrpt::Clock::time_point stamp) const;

	const TOptions& options() const { return m_options; }

   private:
	TOptions m_options;
};

}  // namespace lvf::simulation
