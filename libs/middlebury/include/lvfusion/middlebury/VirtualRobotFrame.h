#pragma once
// The robot frame the import invents around a Middlebury camera (DESIGN.md's
// robot frame): origin on the fitted floor right below the left camera, x
// forward (the optical axis projected onto the floor), y left, z up (the
// floor normal). The left camera's pose in it is the stereo observation's
// cameraPose; the synthesised laser sits at its origin.

#include <lvfusion/middlebury/FloorFit.h>

#include <Eigen/Core>
#include <mrpt/poses/CPose3D.h>

namespace lvf::middlebury
{
class VirtualRobotFrame
{
   public:
	explicit VirtualRobotFrame(const FloorPlane& floor);

	/** The left camera in the robot frame, MRPT camera axes (x right, y down,
	 * z forward): a level camera at height H is CPose3D(0,0,H,-90deg,0,-90deg). */
	const mrpt::poses::CPose3D& cameraPose() const { return m_cameraPose; }

	/** A left-camera-frame point in the robot frame. */
	Eigen::Vector3d toRobot(const Eigen::Vector3d& camera) const
	{
		return m_rotation * camera + Eigen::Vector3d(0, 0, m_height);
	}
	/** A left-camera-frame direction in the robot frame. */
	Eigen::Vector3d directionToRobot(const Eigen::Vector3d& camera) const
	{
		return m_rotation * camera;
	}

	double cameraHeight() const { return m_height; }	//!< [m] above the floor
	/** How far the optical axis looks below the horizontal [deg]. */
	double tiltDeg() const { return m_tiltDeg; }
	/** Rotation about the optical axis [deg]: how far the image's x axis
	 * (to the right) rises above the floor plane. */
	double rollDeg() const { return m_rollDeg; }

   private:
	Eigen::Matrix3d m_rotation;	 //!< rows: robot x, y, z in camera coordinates
	double m_height, m_tiltDeg, m_rollDeg;
	mrpt::poses::CPose3D m_cameraPose;
};

}  // namespace lvf::middlebury
