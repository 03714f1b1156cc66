#pragma once
// Global path planning on an occupancy grid by value iteration (paper §7,
// Fig. 14c-d): grow the obstacles by the robot's radius (TraversableGrid),
// compute the cost-to-go to the goal (ValueFunction.h), then descend it from
// the start: each step goes to the neighbour with the least move cost plus
// cost-to-go, which strictly decreases the value, so it ends at the goal.

#include <lvfusion/planning/ValueFunction.h>
#include <mrpt/config/CLoadableOptions.h>

#include <string>
#include <vector>

namespace lvf::planning
{
enum class PlanOutcome
{
	Found,
	Unreachable,  //!< no traversable path links start and goal
	SweepsExhausted,  //!< max_sweeps ran out before the values reached the start
	StartOutsideMap,
	GoalOutsideMap,
	StartBlocked,  //!< the robot's disc at the start overlaps an obstacle
	GoalBlocked
};

/** What an outcome means, for one line of a report ("start is outside the map"). */
std::string describe(PlanOutcome outcome);

class ValueIterationPlanner
{
   public:
	/** INI section [ValueIterationPlanner]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		double robotRadius = 0.30;	//!< obstacles are grown by this [m]
		/** Cells whose MRPT value (probability of being free) is below this
		 * are obstacles. 0.5: cells more likely occupied than free; cells
		 * never observed (0.5) are not, or the robot could not even stand
		 * where its own 180-degree laser never looked (behind it). */
		double obstacleBelow = 0.5;
		int maxSweeps = 100000;	 //!< safety bound on value-iteration sweeps
		double tolerance = 0;  //!< converged when no value changes by more [m]

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	struct Result
	{
		PlanOutcome outcome = PlanOutcome::Unreachable;
		/** start, the centres of the cells descended through, goal [m]. */
		std::vector<mrpt::math::TPoint2D> path;
		double costToGo = 0;  //!< value at the start cell [m] (grid path length)
		size_t sweeps = 0;
		bool converged = false;
		bool found() const { return outcome == PlanOutcome::Found; }
	};

	ValueIterationPlanner() = default;
	explicit ValueIterationPlanner(const TOptions& options) : m_options(options) {}

	Result plan(
		const mrpt::maps::COccupancyGridMap2D& map, const mrpt::math::TPoint2D& start,
		const mrpt::math::TPoint2D& goal) const;
	/** The same on a grid already grown (to plan several times on one map). */
	Result plan(
		const TraversableGrid& grid, const mrpt::math::TPoint2D& start,
		const mrpt::math::TPoint2D& goal) const;

	const TOptions& options() const { return m_options; }

   private:
	TOptions m_options;
};

}  // namespace lvf::planning
