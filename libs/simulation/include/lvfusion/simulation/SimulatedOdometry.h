#pragma once
// Dead reckoning with noise that grows with distance travelled and angle
// turned, accumulated frame by frame as a real wheel odometer drifts.

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/poses/CPose2D.h>

namespace lvf::simulation
{
class SimulatedOdometry
{
   public:
	/** INI section [SimulatedOdometry]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		double xyStdPerMetre = 0.02;  //!< position noise per metre driven [m/m]
		double yawStdPerRadian = 0.03;	//!< heading noise per radian turned [rad/rad]
		double yawStdPerMetre = 0.01;  //!< heading noise per metre driven [rad/m]

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;
	};

	SimulatedOdometry(const TOptions& options, uint64_t seed);

	/** Reading after the robot moved to `truePose` (first call: the start). */
	mrpt::poses::CPose2D update(const mrpt::poses::CPose2D& truePose);

   private:
	TOptions m_options;
	uint64_t m_seed;
	size_t m_steps = 0;
	mrpt::poses::CPose2D m_lastTrue, m_reading;
};

}  // namespace lvf::simulation
