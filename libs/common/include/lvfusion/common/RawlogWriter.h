#pragma once
// Writes MRPT rawlogs (gzip-compressed, as MRPT's own tools read them) in
// either of MRPT's two layouts:
//  - ActionsSensoryFrames: CActionCollection (odometry increment) followed by
//    a CSensoryFrame per frame, what pf-localization and RawLogViewer's
//    "maps" tools expect;
//  - Observations: a flat, time-ordered sequence of CObservation objects,
//    odometry as CObservationOdometry.

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CSerializable.h>

#include <memory>
#include <string>
#include <vector>

namespace lvf::common
{
class GzWriterThread;

enum class RawlogFormat
{
	ActionsSensoryFrames,
	Observations
};

/** "sf" / "obs" (as on lvf-* command lines); throws InputError otherwise. */
RawlogFormat parseRawlogFormat(const std::string& name, const std::string& source);

struct RawlogFrame
{
	mrpt::Clock::time_point timestamp;
	/** Absolute odometry reading at `timestamp` (robot's own dead reckoning). */
	mrpt::poses::CPose2D odometry;
	/** Sensor observations of this frame, in time order. */
	std::vector<mrpt::obs::CObservation::Ptr> observations;
};

class RawlogWriter
{
   public:
	RawlogWriter(
		const std::string& path, RawlogFormat format,
		mrpt::obs::CActionRobotMovement2D::TMotionModelOptions motionModel =
			{});
	~RawlogWriter();

	void append(const RawlogFrame& frame);
	/** Writes one rawlog entry as it is (an observation, an action
	 * collection or a sensory frame), for tools that pass a log through.
	 * Entries are written on a thread of their own: this and append()
	 * throw the InputError naming the file once an earlier entry could
	 * not be written. */
	void appendEntry(const mrpt::serialization::CSerializable& entry);
	/** Waits until everything is written and closes; InputError naming
	 * the file if any of it could not be written (a full disk). The
	 * destructor closes too, silently: call this to know that the file is
	 * whole. */
	void close();

	size_t framesWritten() const { return m_frames; }

   private:
	/** Serializes one entry and hands its bytes to the writing thread. */
	void write(const mrpt::serialization::CSerializable& object);

	/** Deflates and writes on a thread of its own, while the caller goes
	 * on (GzWriterThread.h). */
	std::unique_ptr<GzWriterThread> m_out;
	RawlogFormat m_format;
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions m_motionModel;
	mrpt::poses::CPose2D m_lastOdometry;
	size_t m_frames = 0;
};

}  // namespace lvf::common
