// The text files the apps read beside a rawlog, chosen by the input's first
// byte so one corpus explores all four: truth scans (lvf-fuse --truth), pose
// files (lvf-map's ground truth), Middlebury calib.txt and disparity PFM
// (lvf-import-middlebury).
#include "FuzzInput.h"

#include <lvfusion/metrics/PoseTrajectory.h>
#include <lvfusion/metrics/TruthScanFile.h>
#include <lvfusion/middlebury/MiddleburyCalib.h>
#include <lvfusion/middlebury/PfmFile.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	if (size == 0) return 0;
	const std::string& path = lvf::fuzz::inputFile(data + 1, size - 1, ".txt");
	lvf::fuzz::expectInputErrorOnly([&] {
		switch (data[0] % 4)
		{
			case 0: lvf::metrics::readTruthScans(path); break;
			case 1: lvf::metrics::readPoseFile(path); break;
			case 2: lvf::middlebury::readMiddleburyCalib(path); break;
			default: lvf::middlebury::readPfm(path); break;
		}
	});
	return 0;
}
