#include "MapRun.h"

#include <lvfusion/common/InputError.h>
#include <lvfusion/common/ObservationLabels.h>
#include <lvfusion/common/OdometryReadings.h>
#include <lvfusion/common/RawlogReader.h>
#include <mrpt/obs/CObservationOdometry.h>

namespace lvf::apps
{
using mrpt::obs::CObservation2DRangeScan;

namespace
{
bool isFused(const CObservation2DRangeScan& s) { return s.sensorLabel == lvf::common::kFusedScanLabel; }

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
/** A log's own actions may carry no time stamp (MRPT's older sample logs,
 * localization_demo.rawlog): they take their frame's scan's, since MRPT's
 * ICP-SLAM asserts one. */
void stampActions(mrpt::obs::CActionCollection& actions, mrpt::Clock::time_point stamp)
{
	for (size_t i = 0; i < actions.size(); i++)
		if (const auto action = actions.get(i); action->timestamp == INVALID_TIMESTAMP) action->timestamp = stamp;
}
}  // namespace

MapRun loadMapRun(
	const std::string& path, const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions& obsOnlyModel)
{
	MapRun run;
	bool odometrySeen = false;
	// Sensory-frame layout: the action before a frame moves the robot to it.
	mrpt::obs::CActionCollection::Ptr pendingActions;
	mrpt::poses::CPose2D deadReckoning, lastStepOdometry;
	// Observations layout: the odometry readings (a frame's reading may come
	// after its scan), and the steps whose odometry and action are taken from
	// them once all are read.
	lvf::common::OdometryReadings readings;
	std::vector<size_t> stepsByReadings;

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
	// One pass, keeping only the scans: a long log's images would not fit.
	lvf::common::RawlogReader reader(path);
	while (const auto entry = reader.next())
	{
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(entry))
			readings.add(odo->timestamp, odo->odometry);
		else if (auto actions = std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(entry))
		{
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
			stampActions(*step.action, step.laser->timestamp);
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
			stepsByReadings.push_back(run.steps.size());
			run.steps.push_back(step);
		}
	}
	const bool odometryReadings = !readings.empty();
	mrpt::poses::CPose2D usedOdometry = odometryReadings ? readings.earliest() : mrpt::poses::CPose2D();
	for (size_t i : stepsByReadings)
	{
		auto& step = run.steps[i];
		const auto t = step.laser->timestamp;
		step.odometry = odometryReadings ? readings.poseAt(t) : usedOdometry;
		step.action = odometryAction(step.odometry - usedOdometry, obsOnlyModel, t);
		usedOdometry = step.odometry;
	}
	if (run.steps.empty())
		throw lvf::common::InputError(path, "", "no 2D laser scan (CObservation2DRangeScan) in the rawlog");
	if (!odometrySeen && !odometryReadings)
		throw lvf::common::InputError(
			path, "", "no odometry (neither CActionRobotMovement2D nor CObservationOdometry): the particle filter needs it");
	return run;
}

}  // namespace lvf::apps
