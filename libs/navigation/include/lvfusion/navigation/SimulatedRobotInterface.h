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

	// The navigator's events: the loop reads its state instead
	// (ClosedLoop: NAV_ERROR and IDLE end a step's navigation).
	void sendNavigationEndDueToErrorEvent() override {}
	void sendWaySeemsBlockedEvent() override {}
	void sendCannotGetCloserToBlockedTargetEvent() override {}
	void sendNavigationStartEvent() override {}
	void sendNavigationEndEvent() override {}
	void sendApparentCollisionEvent() override {}

   private:
	mrpt::kinematics::CVehicleSimul_DiffDriven& m_vehicle;
	const LocalObstacleGrid& m_grid;
	double m_obstacleRange;
};

}  // namespace lvf::navigation
