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

/** The relative speed to ask of the navigator at an intermediary subgoal
 * for method `name`: 1 (no slowing down on the way through), except for
 * methods that need MRPT's approach slow-down switched on to move at all.
 * MRPT 2.5 turns the slow-down off for targets with targetDesiredRelSpeed
 * >= 0.11 (CAbstractPTGBasedReactive), and CHolonomicVFF then never sets
 * NavOutput::desiredSpeed, which stays 0: measured, VFF never moved with
 * guidance on. Its default rel speed (0.05) keeps the slow-down, which only
 * acts within TARGET_SLOW_APPROACHING_DISTANCE of the subgoal. */
double subgoalRelativeSpeed(const std::string& name);

}  // namespace lvf::navigation
