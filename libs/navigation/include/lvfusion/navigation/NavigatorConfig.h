#pragma once
// MRPT's reactive navigator configuration, complete: MRPT 2.5's
// CReactiveNavigationSystem reads only the keys it knows and keeps defaults
// for the rest, so the only complete list of what a run uses is the
// navigator's own saveConfigFile() after loading the user's file (every
// section, key and MRPT's comment: PTGs, every registered holonomic method,
// motion deciders). lvf-navigate --dump-config prints it.

#include <lvfusion/common/InputError.h>
#include <mrpt/nav/reactive/CAbstractNavigator.h>

#include <string>

namespace lvf::navigation
{
/** `navigatorConfig` (MRPT INI text) as MRPT's navigator reads it, with
 * every key it would use, and `holonomicMethod` as the method. */
std::string completeNavigatorConfig(const std::string& navigatorConfig, const std::string& holonomicMethod);

/** Throws lvf::common::InputError naming `source` (the INI file) when
 * MRPT's navigator cannot load `navigatorConfig` with `holonomicMethod`: no
 * or unknown PTGs, a robot shape whose xs and ys differ in length. MRPT
 * throws its own exceptions for these; checked before anything is written.
 * (The PTGs' parameter checks run only when their look-up tables are built,
 * seconds of work: a run turns those into navigatorRefuses().) */
void requireNavigatorAccepts(const std::string& navigatorConfig, const std::string& holonomicMethod,
	const std::string& source);

/** MRPT's exception `e` on loading or initialising a navigator from
 * `source`, as one line naming the file. */
lvf::common::InputError navigatorRefuses(const std::string& source, const std::exception& e);

/** Errors-only logging and no time profiler printing on destruction. */
void quietNavigator(mrpt::nav::CAbstractNavigator& navigator);

}  // namespace lvf::navigation
