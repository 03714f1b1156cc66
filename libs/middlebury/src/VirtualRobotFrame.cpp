#include <lvfusion/middlebury/VirtualRobotFrame.h>

#include <mrpt/core/bits_math.h>
#include <mrpt/math/CMatrixFixed.h>
#include <mrpt/math/CVectorFixed.h>

#include <cmath>

namespace lvf::middlebury
{
VirtualRobotFrame::VirtualRobotFrame(const FloorPlane& floor) : m_height(floor.offset)
{
	// Camera coordinates throughout: the floor normal is robot z; the optical
	// axis (camera z) with its normal component removed is robot x (it never
	// vanishes: fitFloor keeps the normal within 45 deg (maxNormalAngleDeg)
	// of the camera's -y).
	const Eigen::Vector3d z = floor.normal;
	const Eigen::Vector3d x = (Eigen::Vector3d::UnitZ() - z.z() * z).normalized();
	const Eigen::Vector3d y = z.cross(x);
	m_rotation.row(0) = x;
	m_rotation.row(1) = y;
	m_rotation.row(2) = z;
	m_tiltDeg = mrpt::RAD2DEG(std::asin(-z.z()));
	m_rollDeg = mrpt::RAD2DEG(std::asin(z.x()));

	// The camera centre (camera origin) is at height `offset` straight above
	// the robot origin; the columns of m_rotation are the camera's axes in
	// robot coordinates, i.e. its orientation.
	mrpt::math::CMatrixDouble33 rot;
	for (int r = 0; r < 3; r++)
		for (int c = 0; c < 3; c++) rot(r, c) = m_rotation(r, c);
	mrpt::math::CVectorFixedDouble<3> position;
	position[0] = 0, position[1] = 0, position[2] = m_height;
	m_cameraPose = mrpt::poses::CPose3D::FromRotationAndTranslation(rot, position);
}

}  // namespace lvf::middlebury
