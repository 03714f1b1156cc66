#include <lvfusion/common/IniSection.h>
#include <lvfusion/simulation/SimulatedOdometry.h>
#include <mrpt/math/wrap2pi.h>
#include <opencv2/core.hpp>

#include <array>
#include <cmath>
#include <random>

namespace lvf::simulation
{
using lvf::common::writeOption;

namespace
{
/** `seed` scrambled by the standard library's seed sequence. cv::RNG is a
 * multiply-with-carry generator: seeded with consecutive small numbers (a
 * step's), its first Gaussian draws are a lattice, not noise (RMS
 * 0.001-0.25 of the asked spread over seeds 1-301; 0.2-1.5 with a constant
 * XORed in). */
uint64_t scrambled(uint64_t seed)
{
	std::seed_seq sequence{static_cast<uint32_t>(seed), static_cast<uint32_t>(seed >> 32)};
	std::array<uint32_t, 2> words{};
	sequence.generate(words.begin(), words.end());
	return (uint64_t(words[1]) << 32) | words[0];
}
}  // namespace

void SimulatedOdometry::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	xyStdPerMetre = ini.real("xy_std_per_m", xyStdPerMetre, 0, 1);
	yawStdPerRadian = ini.real("yaw_std_per_rad", yawStdPerRadian, 0, 1);
	yawStdPerMetre = ini.real("yaw_std_per_m", yawStdPerMetre, 0, 1);
	ini.rejectUnknownKeys();
}

void SimulatedOdometry::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "xy_std_per_m", xyStdPerMetre, "position noise per metre driven [m/m]");
	writeOption(c, s, "yaw_std_per_rad", yawStdPerRadian, "heading noise per radian turned [rad/rad]");
	writeOption(c, s, "yaw_std_per_m", yawStdPerMetre, "heading noise per metre driven [rad/m]");
}

SimulatedOdometry::SimulatedOdometry(const TOptions& options, uint64_t seed)
	: m_options(options), m_seed(seed)
{
}

mrpt::poses::CPose2D SimulatedOdometry::update(
	const mrpt::poses::CPose2D& truePose)
{
	if (m_steps++ == 0)
	{
		m_lastTrue = m_reading = truePose;
		return m_reading;
	}
	const mrpt::poses::CPose2D step = truePose - m_lastTrue;
	const double dist = std::hypot(step.x(), step.y());
	const double turn = std::abs(mrpt::math::wrapToPi(step.phi()));
	// The three draws are taken in a stated order: a function's arguments
	// are evaluated in none, and the heading took a first draw that, before
	// the seed was scrambled, was almost nothing.
	cv::RNG rng(scrambled(m_seed * 1000003ULL + m_steps));
	const double xyStd = m_options.xyStdPerMetre * dist;
	const double yawStd =
		m_options.yawStdPerRadian * turn + m_options.yawStdPerMetre * dist;
	const double dx = rng.gaussian(xyStd);
	const double dy = rng.gaussian(xyStd);
	const double dyaw = rng.gaussian(yawStd);
	const mrpt::poses::CPose2D noisyStep(step.x() + dx, step.y() + dy, step.phi() + dyaw);
	m_reading = m_reading + noisyStep;
	m_lastTrue = truePose;
	return m_reading;
}

}  // namespace lvf::simulation
