#pragma once
// lvf-fuse's output log: every input entry as it was, each followed by the
// results of the frames that end at it (inside the sensory frame in that
// layout). A log fused before -- lvf-fuse's own output, lvf-navigate's run
// -- already holds FUSED scans and EVAL pictures: those are an earlier
// fusion's, and they are left out, or the output would hold two FUSED scans
// a frame that MRPT's tools and lvf-map would both take. The output holds
// this run's alone (no EVAL picture where --eval-every skips a frame, no
// FUSED scan for a frame this run could not pair).

#include "FrameStream.h"

#include <lvfusion/common/RawlogWriter.h>

namespace lvf::apps
{
class FusedLogWriter
{
   public:
	explicit FusedLogWriter(lvf::common::RawlogWriter& out) : m_out(out) {}

	void write(const mrpt::serialization::CSerializable& entry, const FrameStream::Results& results);

	/** The earlier fusion's observations left out so far. */
	size_t replaced() const { return m_replaced; }

   private:
	lvf::common::RawlogWriter& m_out;
	size_t m_replaced = 0;
};

}  // namespace lvf::apps
