#pragma once
// MRPT's reactive navigator configuration, complete: MRPT 2.5's
// CReactiveNavigationSystem reads only the keys it knows and keeps defaults
// for the rest, so the only complete list of what a run uses is the
// navigator's own saveConfigFile() after loading the user's file (every
// section, key and MRPT's comment: PTGs, every registered holonomic method,
// motion deciders). lvf-navigate --dump-config prints it.

#include <mrpt/nav/reactive/CAbstractNavigator.h>

#include <string>

namespace lvf::navigation
{
/** `navigatorConfig` (MRPT INI text) as MRPT's navigator reads it, with
 * every key it would use, and `holonomicMethod` as the method. */
std::string completeNavigatorConfig(const std::string& navigatorConfig, const std::string& holonomicMethod);

/** Errors-only logging and no time profiler printing on destruction. */
void quietNavigator(mrpt::nav::CAbstractNavigator& navigator);

}  // namespace lvf::navigation
