#pragma once
// The common frame of every lvf-* program: run the body, turn a bad input
// (InputError, a bad command line) into exactly one line on stderr and exit
// status 2, and anything unexpected into one line and status 1.

#include <functional>
#include <string>

namespace TCLAP
{
class CmdLine;
}

namespace lvf::common
{
constexpr int kExitOk = 0;
constexpr int kExitInternalError = 1;
constexpr int kExitBadInput = 2;

int runApp(const std::string& appName, const std::function<int()>& body);

/** Parses the command line (once per CmdLine, which must still have its
 * default output); a bad argument becomes an InputError (one line,
 * status 2) instead of TCLAP's multi-line usage dump. Returns false when the
 * program should just exit with success (--help, --version). */
bool parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv);

/** True when stdout is a terminal and CI is not set: progress bars only then. */
bool interactiveTerminal();

}  // namespace lvf::common
