// MRPT can load liblvfusion.so as a plugin and then knows its classes by name.

#include <gtest/gtest.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/system/os.h>

#include <string>
#include <utility>
#include <vector>

TEST(Plugin, LoadsAndRegistersClassesByName)
{
	const std::string plugin = LVF_PLUGIN_PATH;
	EXPECT_EQ(mrpt::rtti::findRegisteredClass("CStereoLaserSimulator"), nullptr)
		<< "the test must not link the registry itself";
	std::string errors;
	ASSERT_TRUE(mrpt::system::loadPluginModules(plugin, errors)) << errors;

	// (name looked up, class it must create)
	for (const auto& [name, full] : std::vector<std::pair<std::string, std::string>>{
			 {"CStereoLaserSimulator", "lvf::simulation::CStereoLaserSimulator"},
			 {"lvf::simulation::CStereoLaserSimulator", "lvf::simulation::CStereoLaserSimulator"},
			 {"CLaserStereoFusion", "lvf::fusion::CLaserStereoFusion"},
			 {"CHolonomicVFH", "lvf::vfh::CHolonomicVFH"},
			 {"CLogFileRecord_VFH", "lvf::vfh::CLogFileRecord_VFH"}})
	{
		const auto* cls = mrpt::rtti::findRegisteredClass(name);
		ASSERT_NE(cls, nullptr) << name;
		const auto obj = mrpt::rtti::classFactory(name);
		ASSERT_TRUE(obj) << name;
		EXPECT_EQ(obj->GetRuntimeClass()->className, full);
	}
}
