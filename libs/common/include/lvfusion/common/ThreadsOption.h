#pragma once
// --threads N, for the programs that run the fusion: the size of OpenCV's
// thread pool, on which the model check and the depth search run their rows
// (RowBands.h). The results are the same on any number of threads.
// Header-only: its users (the apps) link OpenCV.

#include <lvfusion/common/InputError.h>
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <opencv2/core/utility.hpp>

#include <string>

namespace lvf::common
{
class ThreadsOption
{
   public:
	explicit ThreadsOption(TCLAP::CmdLine& cmd)
		: m_arg("", "threads",
			  "Threads for the fusion's model check and depth search (OpenCV's pool; 0: OpenCV's own "
			  "count, one per core; the results are the same on any number) (default 0)",
			  false, 0, "N", cmd)
	{
	}

	/** Sizes OpenCV's pool (0 leaves its default); a negative count is a
	 * bad input. */
	void apply()
	{
		if (m_arg.getValue() < 0) throw InputError("--threads", "", "must be >= 0");
		if (m_arg.getValue() > 0) cv::setNumThreads(m_arg.getValue());
	}

	/** "1 thread", "2 threads": the pool as it is now. */
	static std::string describe()
	{
		const int n = cv::getNumThreads();
		return std::to_string(n) + (n == 1 ? " thread" : " threads");
	}

   private:
	TCLAP::ValueArg<int> m_arg;
};

}  // namespace lvf::common
