#include <lvfusion/common/InputError.h>
#include <lvfusion/navigation/HolonomicMethods.h>
#include <mrpt/nav/holonomic/CAbstractHolonomicReactiveMethod.h>
#include <mrpt/nav/reactive/CAbstractNavigator.h>
#include <mrpt/rtti/CObject.h>

#include <algorithm>

namespace lvf::navigation
{
std::vector<std::string> registeredHolonomicMethods()
{
	mrpt::rtti::registerAllPendingClasses();
	std::vector<std::string> names;
	for (const auto* c : mrpt::rtti::getAllRegisteredClassesChildrenOf(
			 CLASS_ID(mrpt::nav::CAbstractHolonomicReactiveMethod)))
		if (c->ptrCreateObject)
		{
			// Registered as "mrpt::nav::CHolonomicND"; INI files and the
			// navigator's factory use the bare class name.
			const std::string full = c->className;
			const auto colon = full.rfind("::");
			names.push_back(colon == std::string::npos ? full : full.substr(colon + 2));
		}
	std::sort(names.begin(), names.end());
	return names;
}

void requireHolonomicMethod(const std::string& name, const std::string& source)
{
	const auto known = registeredHolonomicMethods();
	if (std::find(known.begin(), known.end(), name) != known.end()) return;
	std::string list;
	for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
	throw lvf::common::InputError(
		source, "", "'" + name + "' is not a registered holonomic method (registered: " + list + ")");
}

double subgoalRelativeSpeed(const std::string& name)
{
	if (name == "CHolonomicVFF") return mrpt::nav::CAbstractNavigator::TargetInfo().targetDesiredRelSpeed;
	return 1.0;
}

}  // namespace lvf::navigation
