#include <lvfusion/vfh/CLogFileRecord_VFH.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/stl_serialization.h>

IMPLEMENTS_SERIALIZABLE(CLogFileRecord_VFH, mrpt::nav::CHolonomicLogFileRecord, lvf::vfh)

namespace lvf::vfh
{
uint8_t CLogFileRecord_VFH::serializeGetVersion() const { return 0; }

void CLogFileRecord_VFH::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << dirs_eval << primaryHistogram << binaryHistogram << maskedHistogram
		<< candidateDirections << candidateCosts << targetDirection << chosenDirection << found
		<< speedFactor << tauLow << tauHigh;
}

void CLogFileRecord_VFH::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
			in >> dirs_eval >> primaryHistogram >> binaryHistogram >> maskedHistogram >>
				candidateDirections >> candidateCosts >> targetDirection >> chosenDirection >>
				found >> speedFactor >> tauLow >> tauHigh;
			break;
		default: MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	}
}

}  // namespace lvf::vfh
