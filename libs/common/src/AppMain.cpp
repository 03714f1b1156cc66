#include <lvfusion/common/AppMain.h>
#include <lvfusion/common/InputError.h>
#include <lvfusion/common/ProcessMemory.h>
#include <lvfusion/common/SignalCleanup.h>
#include <lvfusion/common/StagedOutputFiles.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <vector>
#include <unistd.h>

namespace lvf::common
{
int runApp(const std::string& appName, const std::function<int()>& body)
{
	retainLargeAllocations();  // every app handles frame after frame
	try
	{
		installSignalCleanup();	 // no staging folder left by Ctrl-C
		return body();
	}
	catch (const InputError& e)
	{
		std::cerr << appName << ": error: " << withOutputPaths(e.what()) << std::endl;
		return kExitBadInput;
	}
	catch (const std::exception& e)
	{
		std::cerr << appName << ": internal error: " << withOutputPaths(exceptionMessage(e)) << std::endl;
		return kExitInternalError;
	}
}

namespace
{
class OneLineFailureOutput : public TCLAP::StdOutput
{
   public:
	void failure(TCLAP::CmdLineInterface& cmd, TCLAP::ArgException& e) override
	{
		// TCLAP says only that "one or more" required arguments are missing:
		// name them.
		// Alternatives (CmdLine::xorAdd) are each "required": name them as
		// one, "--out or --outdir".
		std::string missing;
		std::vector<const TCLAP::Arg*> told;
		auto tell = [&](const std::string& names) { missing += (missing.empty() ? "" : ", ") + names; };
		for (const auto& alternatives : cmd.getXorHandler().getXorList())
		{
			std::string names;
			bool anySet = false;
			for (const auto* arg : alternatives)
			{
				names += (names.empty() ? "--" : " or --") + arg->getName();
				anySet |= arg->isSet();
				told.push_back(arg);
			}
			if (!anySet) tell(names);
		}
		for (const auto* arg : cmd.getArgList())
			if (arg->isRequired() && !arg->isSet() && std::find(told.begin(), told.end(), arg) == told.end())
				tell("--" + arg->getName());
		if (!missing.empty())
			throw InputError("command line", "", "missing required argument(s) " + missing + " (see --help)");
		throw InputError("command line", e.argId(), e.error() + " (see --help)");
	}
};
}  // namespace

bool parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv)
{
	static OneLineFailureOutput output;	 // must outlive cmd
	// CmdLine news its default StdOutput and only deletes it if nobody
	// replaced it: release it here, or every run leaks it.
	delete cmd.getOutput();
	cmd.setOutput(&output);
	return cmd.parse(argc, argv);
}

bool interactiveTerminal()
{
	const char* ci = std::getenv("CI");
	return ::isatty(STDOUT_FILENO) && !(ci && *ci);
}

}  // namespace lvf::common
