#pragma once
// Per-stage timing for lvf-bench: every frame's milliseconds per stage of a
// method, reported as the median per frame (robust to the odd preempted
// frame on a shared machine, unlike a mean) beside each method's total.

#include <map>
#include <ostream>
#include <string>
#include <vector>

namespace lvf::bench
{
class StageMedians
{
   public:
	/** Records one frame's time [ms] in `stage` of `method`; stages are
	 * printed in the order they were first recorded. */
	void add(const std::string& method, const std::string& stage, double ms);

	/** Median per frame [ms]; 0 if never recorded. */
	double median(const std::string& method, const std::string& stage) const;
	/** Median over frames of the per-frame total of all stages [ms]. */
	double medianTotal(const std::string& method) const;

	/** One line per method, after `indent`: each stage's median, the
	 * total's median, and the total's ratio against `baseline`'s. */
	void print(std::ostream& out, const std::string& baseline, const std::string& indent = "  ") const;

   private:
	struct Method
	{
		std::vector<std::string> stageOrder;
		std::map<std::string, std::vector<double>> perStage;
	};
	std::vector<std::string> m_methodOrder;
	std::map<std::string, Method> m_methods;
};

}  // namespace lvf::bench
