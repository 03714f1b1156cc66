#pragma once
// Holonomic methods are found by class name in MRPT's class registry, as
// CReactiveNavigationSystem itself finds them, so any method registered
// there (MRPT's, or ours once the plugin is loaded) can steer.

#include <string>
#include <vector>

namespace lvf::navigation
{
/** Names of every registered mrpt::nav::CAbstractHolonomicReactiveMethod. */
std::vector<std::string> registeredHolonomicMethods();

/** Throws lvf::common::InputError naming `source` (e.g. "--method") and the
 * registered methods when `name` is not one of them. */
void requireHolonomicMethod(const std::string& name, const std::string& source);

}  // namespace lvf::navigation
