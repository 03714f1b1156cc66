#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogWriter.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

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
	: m_path(path),
	  m_out(std::make_unique<mrpt::io::CFileGZOutputStream>()),
	  m_format(format),
	  m_motionModel(motionModel)
{
	// Level 1: most of a log is camera images (MRPT 2 stores them raw),
	// which compress little at any level (to about 3/4 at level 1), so a
	// higher one costs time for next to nothing.
	if (!m_out->open(path, 1))
		throw InputError(path, "", "cannot open for writing");
}

RawlogWriter::~RawlogWriter() = default;

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

void RawlogWriter::write(const mrpt::serialization::CSerializable& object)
{
	try
	{
		auto arch = mrpt::serialization::archiveFrom(*m_out);
		arch << object;
	}
	catch (const std::exception&)
	{
		// MRPT's archive throws with its own stack of frames; one line is
		// what every bad input and output gets here.
		throw InputError(m_path, "", "cannot be written (disk full?)");
	}
}

void RawlogWriter::close() { m_out->close(); }

}  // namespace lvf::common
