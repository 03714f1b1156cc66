// --config FILE.ini, as every app opens it (openIniFile: the line check,
// then MRPT's own parser and preprocessor), then the fusion's, the
// simulated sensors' and the VFH's sections read strictly (IniSection.h).
#include "FuzzInput.h"

#include <lvfusion/common/IniSection.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/vfh/VfhParameters.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string& path = lvf::fuzz::inputFile(data, size, ".ini");
	lvf::fuzz::expectInputErrorOnly([&] {
		const auto ini = lvf::common::openIniFile(path);
		lvf::fusion::CLaserStereoFusion::TOptions fusion;
		fusion.loadFromConfigFile(*ini, "CLaserStereoFusion");
	});
	lvf::fuzz::expectInputErrorOnly([&] {
		const auto ini = lvf::common::openIniFile(path);
		lvf::simulation::CStereoLaserSimulator::TOptions sensors;
		sensors.loadFromConfigFile(*ini, "CStereoLaserSimulator");
	});
	lvf::fuzz::expectInputErrorOnly([&] {
		const auto ini = lvf::common::openIniFile(path);
		lvf::vfh::VfhParameters vfh;
		vfh.loadFromConfigFile(*ini, "VfhPlus");
	});
	return 0;
}
