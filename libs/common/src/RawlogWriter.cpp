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
	: m_out(std::make_unique<mrpt::io::CFileGZOutputStream>()),
	  m_format(format),
	  m_motionModel(motionModel)
{
	// Level 1: images are already zip-compressed by CImage's serialization,
	// so a higher gzip level costs time and saves next to nothing.
	if (!m_out->open(path, 1))
		throw InputError(path, "", "cannot open for writing");
}

RawlogWriter::~RawlogWriter() = default;

void RawlogWriter::append(const RawlogFrame& frame)
{
	auto arch = mrpt::serialization::archiveFrom(*m_out);
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
		arch << actions << sf;
	}
	else
	{
		auto odo = std::make_shared<mrpt::obs::CObservationOdometry>();
		odo->sensorLabel = "ODOMETRY";
		odo->timestamp = frame.timestamp;
		odo->odometry = frame.odometry;
		arch << *odo;
		for (const auto& o : frame.observations) arch << *o;
	}
	m_lastOdometry = frame.odometry;
	++m_frames;
}

void RawlogWriter::appendEntry(const mrpt::serialization::CSerializable& entry)
{
	auto arch = mrpt::serialization::archiveFrom(*m_out);
	arch << entry;
}

void RawlogWriter::close() { m_out->close(); }

}  // namespace lvf::common
