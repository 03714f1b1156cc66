#include <lvfusion/plugin/registerAllClasses.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/simulation/CStereoLaserSimulator.h>
#include <lvfusion/vfh/CHolonomicVFH.h>
#include <mrpt/rtti/CObject.h>

namespace lvf
{
void registerAllClasses()
{
	// One line per class, as MRPT's own registerAllClasses.cpp files do.
	mrpt::rtti::registerClass(CLASS_ID(lvf::simulation::CStereoLaserSimulator));
	mrpt::rtti::registerClass(CLASS_ID(lvf::fusion::CLaserStereoFusion));
	mrpt::rtti::registerClass(CLASS_ID(lvf::vfh::CHolonomicVFH));
	mrpt::rtti::registerClass(CLASS_ID(lvf::vfh::CLogFileRecord_VFH));
}
}  // namespace lvf
