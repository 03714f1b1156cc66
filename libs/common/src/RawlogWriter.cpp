#include "GzWriterThread.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogWriter.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>

namespace lvf::common
{
RawlogFormat parseRawlogFormat(const std::string& name, const std::string& source)
{
	if (name == "sf") return RawlogFormat::ActionsSensoryFrames;
	if (name == "obs") return RawlogFormat::Observations;
	throw InputError(
		source, "", "unknown rawlog format '" + name + "' (use sf or obs)");
}

RawlogWriter::RawlogWriter(
	const std::string& path, RawlogFormat format,
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel)
	// igzip's level 2: most of a log is camera images (MRPT 2 stores them
	// raw), which compress little at any level; level 2 is as fast as 1 on
	// them and 7 % smaller, level 3 no smaller (measurements.md, session 47).
	: m_out(std::make_unique<GzWriterThread>(path, 2)), m_format(format), m_motionModel(motionModel)
{
}

RawlogWriter::~RawlogWriter() = default;

void RawlogWriter::write(const mrpt::serialization::CSerializable& object)
{
	// Serialized here, on the caller's thread, and handed over whole.
	m_out->write(archived(object));
}

void RawlogWriter::append(const RawlogFrame& frame)
{
	if (m_format == RawlogFormat::ActionsSensoryFrames)
	{
		mrpt::obs::CActionRobotMovement2D move;
		move.timestamp = frame.timestamp;
		const auto increment = m_frames == 0
			? mrpt::poses::CPose2D()
			: frame.odometry - m_lastOdometry;
		move.computeFromOdometry(increment, m_motionModel);
		mrpt::obs::CActionCollection actions;
		actions.insert(move);
		mrpt::obs::CSensoryFrame sf;
		for (const auto& o : frame.observations) sf.insert(o);
		write(actions);
		write(sf);
	}
	else
	{
		auto odo = std::make_shared<mrpt::obs::CObservationOdometry>();
		odo->sensorLabel = "ODOMETRY";
		odo->timestamp = frame.timestamp;
		odo->odometry = frame.odometry;
		write(*odo);
		for (const auto& o : frame.observations) write(*o);
	}
	m_lastOdometry = frame.odometry;
	++m_frames;
}

void RawlogWriter::appendEntry(const mrpt::serialization::CSerializable& entry) { write(entry); }

void RawlogWriter::close() { m_out->close(); }

}  // namespace lvf::common
