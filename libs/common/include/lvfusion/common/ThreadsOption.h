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
	/** What a count of 0 (the default) means. */
	enum class ByDefault
	{
		EveryCpu,  //!< one thread per CPU
		/** one per CPU but one, for a program whose output rawlog's
		 * compressing thread (GzWriterThread.h) is the slowest part of its
		 * run (lvf-fuse): on two cores, fusing on both beside it made the
		 * fusion's frames 50 % slower for the same wall time. */
		LeaveOneForWriting
	};

	explicit ThreadsOption(TCLAP::CmdLine& cmd, ByDefault byDefault = ByDefault::EveryCpu)
		: m_arg("", "threads",
			  "Threads for the fusion's model check and depth search (OpenCV's pool, at most one per CPU "
			  "the process may use; 0: " +
				  std::string(byDefault == ByDefault::EveryCpu
						  ? "one per CPU"
						  : "one per CPU but one, which the thread that compresses the output rawlog takes") +
				  "; the results are the same on any number) (default 0)",
			  false, 0, "N", cmd),
		  m_leaveOne(byDefault == ByDefault::LeaveOneForWriting)
	{
	}

	/** Sizes OpenCV's pool; a negative count is a bad input. No more
	 * threads than the CPUs this process may run on (its affinity and
	 * cgroup, as OpenCV counts them): more would only take turns, and TBB,
	 * refusing the extra workers, prints a warning of its own on stderr.
	 * 0: as the constructor was told (ByDefault); every CPU is OpenCV's
	 * own default. */
	void apply()
	{
		if (m_arg.getValue() < 0) throw InputError("--threads", "", "must be >= 0");
		m_asked = m_arg.getValue();
		const int cpus = std::max(1, cv::getNumberOfCPUs());
		if (m_asked > 0) cv::setNumThreads(std::min(m_asked, cpus));
		else if (m_leaveOne) cv::setNumThreads(std::max(1, cpus - 1));
	}

	/** "1 thread", "2 threads": the pool as it is now; by default, that a
	 * CPU was left for writing; with fewer than asked for, why ("1 thread
	 * of 2 asked: 1 CPU available"). */
	std::string describe() const
	{
		const int n = cv::getNumThreads();
		std::string text = std::to_string(n) + (n == 1 ? " thread" : " threads");
		if (m_asked == 0 && m_leaveOne && cv::getNumberOfCPUs() > 1) text += "; another compresses the output";
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
	bool m_leaveOne;
	int m_asked = 0;
};

}  // namespace lvf::common
