#include "FusedLogWriter.h"

#include <lvfusion/common/ObservationLabels.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CSensoryFrame.h>

namespace lvf::apps
{
namespace
{
/** What an earlier fusion added to a log: its fused scans and its
 * evaluation pictures, by the labels lvf-fuse gives them. */
bool fromAnEarlierFusion(const mrpt::obs::CObservation& o)
{
	return (o.sensorLabel == lvf::common::kFusedScanLabel &&
			   dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&o)) ||
		(o.sensorLabel == lvf::common::kEvaluationImageLabel && dynamic_cast<const mrpt::obs::CObservationImage*>(&o));
}
}  // namespace

void FusedLogWriter::write(const mrpt::serialization::CSerializable& entry, const FrameStream::Results& results)
{
	if (const auto* sf = dynamic_cast<const mrpt::obs::CSensoryFrame*>(&entry))
	{
		mrpt::obs::CSensoryFrame rewritten;
		for (const auto& o : *sf)
			if (fromAnEarlierFusion(*o)) m_replaced++;
			else rewritten.insert(o);
		for (const auto& o : results) rewritten.insert(o);
		m_out.appendEntry(rewritten);
		return;
	}
	if (const auto* o = dynamic_cast<const mrpt::obs::CObservation*>(&entry); o && fromAnEarlierFusion(*o))
		m_replaced++;
	else
		m_out.appendEntry(entry);
	for (const auto& o : results) m_out.appendEntry(*o);
}

}  // namespace lvf::apps
