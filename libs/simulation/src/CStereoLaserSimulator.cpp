#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/simulation/GroundTruth.h>

IMPLEMENTS_MRPT_OBJECT(CStereoLaserSimulator, mrpt::rtti::CObject, lvf::simulation)

namespace lvf::simulation
{
using lvf::common::writeOption;

namespace
{
const char* kLaserSection = "SimulatedLaser";
const char* kStereoSection = "SimulatedStereoRig";
const char* kOdometrySection = "SimulatedOdometry";
}  // namespace

void CStereoLaserSimulator::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::rejectUnknownSections(
		source, {section, kLaserSection, kStereoSection, kOdometrySection});
	lvf::common::rejectKeysOfOtherSections<TOptions>(source, section);
	lvf::common::IniSection ini(source, section);
	seed = static_cast<uint32_t>(ini.integer("seed", int(seed), 0));
	framePeriod = ini.real("frame_period", framePeriod, 1e-3, 3600);
	stereoDelay = ini.real("stereo_delay", stereoDelay, -10, 10);
	startTime = ini.real("start_time", startTime, 0);
	ini.rejectUnknownKeys();
	laser.loadFromConfigFile(source, kLaserSection);
	stereo.loadFromConfigFile(source, kStereoSection);
	odometry.loadFromConfigFile(source, kOdometrySection);
}

void CStereoLaserSimulator::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "seed", seed, "seed of all sensor noise; same seed, same rawlog");
	writeOption(c, s, "frame_period", framePeriod, "time between frames [s]");
	writeOption(c, s, "stereo_delay", stereoDelay, "stereo timestamp minus laser timestamp [s]");
	writeOption(c, s, "start_time", startTime, "timestamp of the first frame [s since 1970-01-01 UTC]");
	laser.saveToConfigFile(c, kLaserSection);
	stereo.saveToConfigFile(c, kStereoSection);
	odometry.saveToConfigFile(c, kOdometrySection);
}

CStereoLaserSimulator::CStereoLaserSimulator(World world, const TOptions& options)
	: m_options(options),
	  m_world(std::make_shared<const World>(std::move(world))),
	  m_geometry(std::make_shared<const WorldGeometry>(*m_world)),
	  m_laser(std::make_shared<const SimulatedLaser>(options.laser)),
	  m_stereo(std::make_shared<const SimulatedStereoRig>(options.stereo)),
	  m_odometry(std::make_shared<SimulatedOdometry>(options.odometry, options.seed))
{
}

CStereoLaserSimulator::Frame CStereoLaserSimulator::simulateNextFrame(
	bool withDepth)
{
	if (m_nextFrame >= frameCount())
		throw std::logic_error("CStereoLaserSimulator: no frames left");
	const size_t index = m_nextFrame++;
	return simulateAt(
		index, mrpt::poses::CPose2D(m_world->path[index]),
		m_options.startTime + m_options.framePeriod * static_cast<double>(index), true,
		withDepth);
}

CStereoLaserSimulator::Frame CStereoLaserSimulator::simulateAt(
	size_t index, const mrpt::poses::CPose2D& truePose, double time, bool withStereo,
	bool withDepth)
{
	Frame f;
	f.index = index;
	f.truePose = truePose;
	f.odometry = m_odometry->update(f.truePose);
	f.timestamp = mrpt::Clock::fromDouble(time);
	const mrpt::poses::CPose3D robot(f.truePose);
	// Independent noise streams per frame and sensor, so frame k's noise does
	// not depend on how many random numbers earlier frames drew.
	const uint64_t frameSeed = uint64_t(m_options.seed) * 1000003ULL + f.index;
	f.scan = m_laser->scan(*m_geometry, robot, frameSeed, f.timestamp);
	if (withStereo)
	{
		const auto images = m_stereo->render(*m_geometry, robot, frameSeed, withDepth);
		f.stereo = m_stereo->toObservation(
			images, mrpt::Clock::fromDouble(
						mrpt::Clock::toDouble(f.timestamp) + m_options.stereoDelay));
		f.leftDepth = images.leftDepth;
	}
	f.truthScan = truthScan(*m_world, robot, *f.scan);
	if (withStereo && withDepth)
	{
		// Made on first use: its ray table costs ~8 ms and 2.5 MB, and the
		// closed loop, simulating without depth, never needs it.
		if (!m_seenTruth)
			m_seenTruth = std::make_shared<const StereoSeenTruth>(
				m_options.stereo.stereoCamera(), m_options.stereo.leftCameraPose(),
				m_options.stereo.rightCameraPose(), HeightBand{m_world->robot.obstacleMinHeight, m_world->robot.height});
		f.seenTruthScan = m_seenTruth->scan(f.leftDepth, *f.scan);
	}
	return f;
}

}  // namespace lvf::simulation
