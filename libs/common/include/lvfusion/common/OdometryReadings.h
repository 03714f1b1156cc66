#pragma once
// A rawlog's odometry readings (CObservationOdometry, the observations
// layout) and the pose they give at a scan. lvf-fuse and lvf-map both place
// each scan at the latest reading not after it (the first, before it). A reading may follow its
// scan in the file and a log merged from several sources need not be in time
// order, so the readings are kept sorted by time and looked up by binary
// search: a real robot's log holds tens of thousands of them.

#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <chrono>
#include <utility>
#include <vector>

namespace lvf::common
{
class OdometryReadings
{
   public:
	/** Adds a reading; of readings with equal times the one added last wins
	 * (the file's order). Cheap for readings in time order. */
	void add(mrpt::Clock::time_point t, const mrpt::poses::CPose2D& pose)
	{
		readings_.insert(std::upper_bound(readings_.begin(), readings_.end(), t, laterThan), {t, pose});
	}

	bool empty() const { return readings_.empty(); }

	/** The pose of the latest reading not after `t` (within a microsecond:
	 * logs store times as doubles). Before the first reading, the first: a
	 * scan taken just before the odometry started is where that reading
	 * puts the robot, not at the origin of some other frame. The readings
	 * must not be empty. */
	const mrpt::poses::CPose2D& poseAt(mrpt::Clock::time_point t) const
	{
		const auto next =
			std::upper_bound(readings_.begin(), readings_.end(), t + std::chrono::microseconds(1), laterThan);
		return next == readings_.begin() ? next->second : std::prev(next)->second;
	}

	/** The earliest reading's pose; the readings must not be empty. */
	const mrpt::poses::CPose2D& earliest() const { return readings_.front().second; }

   private:
	using Reading = std::pair<mrpt::Clock::time_point, mrpt::poses::CPose2D>;
	static bool laterThan(mrpt::Clock::time_point t, const Reading& r) { return t < r.first; }

	std::vector<Reading> readings_;	 // by time
};

}  // namespace lvf::common
