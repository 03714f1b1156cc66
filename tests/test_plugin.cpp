// MRPT can load liblvfusion.so as a plugin and then knows its classes by name.

#include <gtest/gtest.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/system/os.h>

TEST(Plugin, LoadsAndRegistersClassesByName)
{
	const std::string plugin = LVF_PLUGIN_PATH;
	EXPECT_EQ(mrpt::rtti::findRegisteredClass("CStereoLaserSimulator"), nullptr)
		<< "the test must not link the registry itself";
	std::string errors;
	ASSERT_TRUE(mrpt::system::loadPluginModules(plugin, errors)) << errors;

	for (const char* name :
		 {"CStereoLaserSimulator", "lvf::simulation::CStereoLaserSimulator"})
	{
		const auto* cls = mrpt::rtti::findRegisteredClass(name);
		ASSERT_NE(cls, nullptr) << name;
		const auto obj = mrpt::rtti::classFactory(name);
		ASSERT_TRUE(obj) << name;
		EXPECT_STREQ(obj->GetRuntimeClass()->className,
					 "lvf::simulation::CStereoLaserSimulator");
	}
}
