#pragma once
// --threads N, for the programs that run the fusion: the size of OpenCV's
// thread pool, on which the model check and the depth search run their rows
// (RowBands.h). The results are the same on any number of threads.
// Header-only: its users (the apps) link OpenCV.

#include <lvfusion/common/InputError.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <string>

namespace lvf::common
{
class ThreadsOption
{
   public:
	/** `work`: what the program runs on the pool, for --help. */
	explicit ThreadsOption(TCLAP::CmdLine& cmd, const std::string& work = "the fusion's model check and depth search")
		: m_arg("", "threads",
			  "Threads for " + work +
				  " (OpenCV's pool, at most one per CPU the process may use; 0: OpenCV's own count, one per "
				  "core; the results are the same on any number) (default 0)",
			  false, 0, "N", cmd)
	{
	}

	/** Sizes OpenCV's pool (0 leaves its default); a negative count is a
	 * bad input. No more threads than the CPUs this process may run on
	 * (its affinity and cgroup, as OpenCV counts them): more would only
	 * take turns, and TBB, refusing the extra workers, prints a warning of
	 * its own on stderr. */
	void apply()
	{
		if (m_arg.getValue() < 0) throw InputError("--threads", "", "must be >= 0");
		m_asked = m_arg.getValue();
		if (m_asked > 0) cv::setNumThreads(std::min(m_asked, std::max(1, cv::getNumberOfCPUs())));
	}

	/** "1 thread", "2 threads": the pool as it is now; with fewer than
	 * asked for, why ("1 thread of 2 asked: 1 CPU available"). */
	std::string describe() const
	{
		const int n = cv::getNumThreads();
		std::string text = std::to_string(n) + (n == 1 ? " thread" : " threads");
		if (m_asked > n)
		{
			const int cpus = cv::getNumberOfCPUs();
			text += " of " + std::to_string(m_asked) + " asked: " + std::to_string(cpus) +
				(cpus == 1 ? " CPU" : " CPUs") + " available";
		}
		return text;
	}

   private:
	TCLAP::ValueArg<int> m_arg;
	int m_asked = 0;
};

}  // namespace lvf::common
