// lvf-fuse's frames: the first laser scan and stereo pair of a rawlog (either
// layout) fused as CLaserStereoFusion does for every frame. The records are
// well-formed MRPT objects with any contents: a calibration that disagrees
// with its images, a zero focal length, NaN ranges or poses, empty images.
#include "FuzzInput.h"

#include <lvfusion/common/RawlogReader.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/obs/CSensoryFrame.h>

namespace
{
struct FirstPair
{
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	mrpt::obs::CObservationStereoImages::Ptr stereo;

	void take(const mrpt::serialization::CSerializable::Ptr& o)
	{
		if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(o))
			for (const auto& obs : *sf) take(obs);
		if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o); s && !scan) scan = s;
		if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservationStereoImages>(o); s && !stereo) stereo = s;
	}
};
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string& path = lvf::fuzz::inputFile(data, size, ".rawlog");
	FirstPair pair;
	lvf::fuzz::expectInputErrorOnly([&] {
		lvf::common::RawlogReader reader(path);
		while (auto o = reader.next())
		{
			pair.take(o);
			if (pair.scan && pair.stereo) break;
		}
	});
	if (!pair.scan || !pair.stereo) return 0;
	lvf::fuzz::expectInputErrorOnly([&] {
		lvf::fusion::CLaserStereoFusion fusion;
		fusion.setMinLoggingLevel(mrpt::system::LVL_ERROR);
		fusion.process(*pair.scan, *pair.stereo, "record 1");
	});
	return 0;
}
