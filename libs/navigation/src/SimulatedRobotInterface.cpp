#include <lvfusion/navigation/SimulatedRobotInterface.h>
#include <mrpt/system/datetime.h>

namespace lvf::navigation
{
SimulatedRobotInterface::SimulatedRobotInterface(
	mrpt::kinematics::CVehicleSimul_DiffDriven& vehicle, const LocalObstacleGrid& grid,
	double obstacleRange)
	: CRobot2NavInterfaceForSimulator_DiffDriven(vehicle),
	  m_vehicle(vehicle),
	  m_grid(grid),
	  m_obstacleRange(obstacleRange)
{
}

bool SimulatedRobotInterface::senseObstacles(
	mrpt::maps::CSimplePointsMap& obstacles, mrpt::system::TTimeStamp& timestamp)
{
	// The same clock as the base class's poses (MRPT's simulator interface
	// stamps them with now()), so the navigator sees them as simultaneous.
	timestamp = mrpt::system::now();
	m_grid.obstaclesNear(mrpt::poses::CPose2D(m_vehicle.getCurrentGTPose()), m_obstacleRange, obstacles);
	return true;
}

}  // namespace lvf::navigation
