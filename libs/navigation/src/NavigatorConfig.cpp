#include <lvfusion/navigation/HolonomicMethods.h>
#include <lvfusion/navigation/LocalObstacleGrid.h>
#include <lvfusion/navigation/NavigatorConfig.h>
#include <lvfusion/navigation/SimulatedRobotInterface.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/nav/reactive/CReactiveNavigationSystem.h>

namespace lvf::navigation
{
namespace
{
/** A navigator that never runs, for reading configurations with: MRPT's
 * navigator needs a robot to exist. */
struct ScratchNavigator
{
	mrpt::kinematics::CVehicleSimul_DiffDriven vehicle;
	const LocalObstacleGrid grid{-1, 1, -1, 1, 0.5, 0.45};
	SimulatedRobotInterface robot{vehicle, grid, 1.0};
	mrpt::nav::CReactiveNavigationSystem navigator{robot, false, false};

	/** Loads `config` with `method` as the holonomic method. */
	ScratchNavigator(const std::string& config, const std::string& method)
	{
		quietNavigator(navigator);
		mrpt::config::CConfigFileMemory in(config);
		in.write("CAbstractPTGBasedReactive", "holonomic_method", method);
		navigator.loadConfigFile(in);
	}
};

/** What MRPT's navigator writes after loading `config` with `method`. */
std::string savedByMrpt(const std::string& config, const std::string& method)
{
	ScratchNavigator scratch(config, method);
	mrpt::config::CConfigFileMemory out;
	scratch.navigator.saveConfigFile(out);
	return out.getContent();
}

/** Adds to `to` every key of `from` it lacks (only in the sections `to`
 * has, if `knownSectionsOnly`). */
void addMissing(mrpt::config::CConfigFileMemory& to, const mrpt::config::CConfigFileMemory& from, bool knownSectionsOnly)
{
	std::vector<std::string> sections, keys;
	from.getAllSections(sections);
	for (const auto& s : sections)
	{
		if (knownSectionsOnly && !to.sectionExists(s)) continue;
		from.getAllKeys(s, keys);
		for (const auto& k : keys)
			if (!to.keyExists(s, k)) to.write(s, k, from.read_string(s, k, ""));
	}
}

}  // namespace

void quietNavigator(mrpt::nav::CAbstractNavigator& navigator)
{
	navigator.setMinLoggingLevel(mrpt::system::LVL_ERROR);
	// MRPT offers only const access to this profiler, which otherwise prints
	// its statistics to stdout when the navigator is destroyed; the object
	// itself is not const, so the cast is well defined.
	const_cast<mrpt::system::CTimeLogger&>(navigator.getDelaysTimeLogger()).enable(false);
}

void requireNavigatorAccepts(const std::string& navigatorConfig, const std::string& holonomicMethod,
	const std::string& source)
{
	try
	{
		ScratchNavigator scratch(navigatorConfig, holonomicMethod);
	}
	catch (const std::exception& e)
	{
		throw navigatorRefuses(source, e);
	}
}

lvf::common::InputError navigatorRefuses(const std::string& source, const std::exception& e)
{
	return lvf::common::InputError(source, "", "MRPT's reactive navigator refuses it: " + lvf::common::exceptionMessage(e));
}

std::string completeNavigatorConfig(const std::string& navigatorConfig, const std::string& holonomicMethod)
{
	// MRPT 2.5 writes the keys of the selected holonomic method only, and of
	// the PTGs only their count: the other methods' sections come from
	// saving with each of them selected, the PTGs' keys (and any other key
	// MRPT reads but does not write) from the user's file as it is; the
	// file's non-MRPT sections are left to their owners.
	mrpt::config::CConfigFileMemory out(savedByMrpt(navigatorConfig, holonomicMethod));
	for (const auto& m : registeredHolonomicMethods())
	{
		if (m == holonomicMethod) continue;
		// A section of a method not selected that MRPT would refuse (a key
		// missing: MRPT's own example files have such) is left as the user
		// wrote it, by the last step; it matters only once selected, and
		// then the run's check names it.
		try
		{
			addMissing(out, mrpt::config::CConfigFileMemory(savedByMrpt(navigatorConfig, m)), false);
		}
		catch (const std::exception&)
		{
		}
	}
	addMissing(out, mrpt::config::CConfigFileMemory(navigatorConfig), true);
	return out.getContent();
}

}  // namespace lvf::navigation
