#pragma once
// What MRPT's reactive navigator sees of our simulated robot: MRPT's own
// differential-drive simulator interface (pose, speeds, motor commands,
// simulated time), with obstacles taken from the local occupancy grid.

#include <lvfusion/navigation/LocalObstacleGrid.h>
#include <mrpt/nav/reactive/CRobot2NavInterfaceForSimulator.h>

namespace lvf::navigation
{
class SimulatedRobotInterface : public mrpt::nav::CRobot2NavInterfaceForSimulator_DiffDriven
{
   public:
	SimulatedRobotInterface(
		mrpt::kinematics::CVehicleSimul_DiffDriven& vehicle, const LocalObstacleGrid& grid,
		double obstacleRange);

	bool senseObstacles(
		mrpt::maps::CSimplePointsMap& obstacles, mrpt::system::TTimeStamp& timestamp) override;

	// The navigator's events, counted for the run's report.
	void sendNavigationEndDueToErrorEvent() override { errorEvents++; }
	void sendWaySeemsBlockedEvent() override { blockedEvents++; }
	void sendCannotGetCloserToBlockedTargetEvent() override { blockedEvents++; }
	void sendNavigationStartEvent() override {}
	void sendNavigationEndEvent() override {}
	void sendApparentCollisionEvent() override {}

	int errorEvents = 0, blockedEvents = 0;

   private:
	mrpt::kinematics::CVehicleSimul_DiffDriven& m_vehicle;
	const LocalObstacleGrid& m_grid;
	double m_obstacleRange;
};

}  // namespace lvf::navigation
