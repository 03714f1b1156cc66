#include "MapRun.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/common/RawlogReader.h>
#include <mrpt/obs/CObservationOdometry.h>

namespace lvf::apps
{
using mrpt::obs::CObservation2DRangeScan;

namespace
{
bool isFused(const CObservation2DRangeScan& s) { return s.sensorLabel == "FUSED"; }

mrpt::obs::CActionCollection::Ptr odometryAction(
	const mrpt::poses::CPose2D& increment,
	const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions& model, mrpt::Clock::time_point stamp)
{
	mrpt::obs::CActionRobotMovement2D move;
	move.computeFromOdometry(increment, model);
	move.timestamp = stamp;	 // MRPT's ICP-SLAM requires one
	auto actions = std::make_shared<mrpt::obs::CActionCollection>();
	actions->insert(move);
	return actions;
}
}  // namespace

MapRun loadMapRun(
	const std::string& path, const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions& obsOnlyModel)
{
	const auto entries = lvf::common::readRawlogEntries(path);
	MapRun run;
	bool odometrySeen = false;
	// Sensory-frame layout: the action before a frame moves the robot to it.
	mrpt::obs::CActionCollection::Ptr pendingActions;
	mrpt::poses::CPose2D deadReckoning, lastStepOdometry;
	// Observations layout: the odometry readings by time (a frame's reading
	// may come after its scan in the file), and the one last used.
	std::vector<std::pair<mrpt::Clock::time_point, mrpt::poses::CPose2D>> readings;
	for (const auto& entry : entries)
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(entry))
			readings.emplace_back(odo->timestamp, odo->odometry);
	const bool odometryReadings = !readings.empty();
	mrpt::poses::CPose2D usedOdometry = odometryReadings ? readings.front().second : mrpt::poses::CPose2D();
	auto odometryAt = [&](mrpt::Clock::time_point t) {
		mrpt::poses::CPose2D latest = usedOdometry;
		for (const auto& [stamp, pose] : readings)	// latest reading not after t
			if (stamp <= t + std::chrono::microseconds(1)) latest = pose;
		return latest;
	};

	auto addFused = [&](const CObservation2DRangeScan::Ptr& fused) {
		// lvf-fuse's FUSED scan carries its laser scan's timestamp.
		for (auto it = run.steps.rbegin(); it != run.steps.rend(); ++it)
			if (it->laser->timestamp == fused->timestamp)
			{
				it->fused = fused;
				run.fusedScans++;
				return;
			}
	};
	for (const auto& entry : entries)
	{
		if (auto actions = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(entry))
		{
			run.sensoryFrames = true;
			if (auto move = actions->getBestMovementEstimation())
			{
				odometrySeen = true;
				deadReckoning = deadReckoning + move->poseChange->getMeanVal();
			}
			// Two actions with no frame between: the filter sees their sum.
			pendingActions = pendingActions ? odometryAction(
												  deadReckoning - lastStepOdometry, obsOnlyModel, actions->get(0)->timestamp)
											: actions;
		}
		else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(entry))
		{
			MapStep step;
			step.laserFrame = std::make_shared<mrpt::obs::CSensoryFrame>();
			for (const auto& o : *sf)
				if (auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(o))
				{
					if (isFused(*scan)) step.fused = scan;
					else
					{
						if (!step.laser) step.laser = scan;
						step.laserFrame->insert(scan);
					}
				}
			if (!step.laser) continue;	// a frame without a scan: its action adds to the next
			step.action = pendingActions ? pendingActions : odometryAction({}, obsOnlyModel, step.laser->timestamp);
			step.odometry = lastStepOdometry = deadReckoning;
			run.fusedScans += step.fused != nullptr;
			run.steps.push_back(step);
			pendingActions.reset();
		}
		else if (auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(entry))
		{
			if (isFused(*scan))
			{
				addFused(scan);
				continue;
			}
			MapStep step;
			step.laser = scan;
			step.laserFrame = std::make_shared<mrpt::obs::CSensoryFrame>();
			step.laserFrame->insert(scan);
			step.odometry = odometryAt(scan->timestamp);
			step.action = odometryAction(step.odometry - usedOdometry, obsOnlyModel, scan->timestamp);
			usedOdometry = step.odometry;
			run.steps.push_back(step);
		}
	}
	if (run.steps.empty())
		throw lvf::common::InputError(path, "", "no 2D laser scan (CObservation2DRangeScan) in the rawlog");
	if (!odometrySeen && !odometryReadings)
		throw lvf::common::InputError(
			path, "", "no odometry (neither CActionRobotMovement2D nor CObservationOdometry): the particle filter needs it");
	return run;
}

}  // namespace lvf::apps
