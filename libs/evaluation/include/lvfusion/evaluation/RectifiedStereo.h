#pragma once
// A calibrated stereo pair brought into the standard rectified geometry:
// undistorted, image rows aligned, the right camera `baseline` metres along
// the left camera's x axis. In it a point at depth Z appears in the right
// image `f * baseline / Z - cxOffset` pixels to the left of its left-image
// column (disparity d = f B / Z), on the same row.
//
// A pair that is already like that (no distortion, equal intrinsics apart
// from cx, parallel cameras, e.g. Middlebury or the default simulator) is used
// as is; otherwise OpenCV's stereoRectify + remap produce it, with the lens
// read as MRPT's own CStereoRectifyMap reads it but with k4-k6 as well
// (OpenCvCamera.h); a fish-eye calibration is refused by name. The rectified
// left camera's pose on the robot is kept so that pixels can be turned into
// robot-frame rays and back.

#include <Eigen/Core>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3D.h>
#include <opencv2/core.hpp>

#include <optional>

namespace lvf::evaluation
{
/** The geometry of a rectified pair, all the later stages need. */
struct RectifiedGeometry
{
	cv::Size size;	//!< image size [px]
	double f = 0;  //!< focal length [px] (fx = fy after rectification)
	double cx = 0, cy = 0;	//!< left principal point [px]
	double cxOffset = 0;  //!< right cx minus left cx [px] (Middlebury's doffs)
	double baseline = 0;  //!< [m]
	/** Rectified left camera on the robot (MRPT camera axes). */
	mrpt::poses::CPose3D leftPose;

	/** f * baseline [px m]: disparity = fB / depth. */
	double fB() const { return f * baseline; }
	/** Normalised ray of pixel (u, v) in the rectified left camera frame. */
	double rayX(double u) const { return (u - cx) / f; }
	double rayY(double v) const { return (v - cy) / f; }
	/** The ray of pixel (u, v) in the robot frame, not normalised: its
	 * component along the camera's axis is 1, so the point at depth Z is
	 * cameraCentre() + Z * robotRay(u, v). */
	Eigen::Vector3d robotRay(double u, double v) const
	{
		return leftPose.getRotationMatrix().asEigen() * Eigen::Vector3d(rayX(u), rayY(v), 1.0);
	}
	/** The rectified left camera's centre in the robot frame [m]. */
	Eigen::Vector3d cameraCentre() const { return {leftPose.x(), leftPose.y(), leftPose.z()}; }
};

/** What rectification did to a pair that the later stages must know, and
 * the images themselves no longer show (all empty where the images are used
 * as they are). */
struct RectificationEffects
{
	/** The left camera's noise std [grey levels] on its image as taken
	 * (ImageNoise.h): interpolation averages neighbouring pixels, so the
	 * rectified image's noise is correlated and the estimator, a 3x3
	 * high-pass, reads less than half of it (2.2 -> 0.9 grey levels on the
	 * simulator's std-2 noise); texture gates set from that would let noise
	 * pass for texture. */
	std::optional<double> sensorNoiseStd;
	/** 255 where a rectified pixel takes some of its value from outside the
	 * camera's image (black there: the corners an `alpha` above 0 keeps);
	 * empty where there is no such pixel. */
	cv::Mat1b leftNotImaged, rightNotImaged;
};

class RectifiedStereo
{
   public:
	/** `alpha`: OpenCV stereoRectify's free scaling where a rig needs
	 * rectifying — 0 keeps only pixels both cameras imaged, cropping the
	 * view's edges (a lens's most), 1 keeps every imaged pixel, with black
	 * corners (RectificationEffects). */
	explicit RectifiedStereo(double alpha = 0) : m_alpha(alpha) {}

	/** Checks and prepares a calibration (both images present, sizes equal
	 * to the calibration, positive focal lengths, a usable baseline).
	 * Throws lvf::common::InputError naming `record` otherwise. Prepared maps
	 * are reused while the calibration does not change. */
	void prepare(
		const mrpt::obs::CObservationStereoImages& obs, const std::string& record);

	/** Both images, grey, rectified. prepare() first. Returns what
	 * rectifying did to the pair (all empty where the images are used as
	 * they are). */
	RectificationEffects rectify(
		const mrpt::obs::CObservationStereoImages& obs, cv::Mat1b& left,
		cv::Mat1b& right) const;

	const RectifiedGeometry& geometry() const { return m_geometry; }
	bool remaps() const { return !m_mapLeftX.empty(); }

   private:
	double m_alpha = 0;
	mrpt::img::TStereoCamera m_calibration;
	mrpt::poses::CPose3D m_cameraPose;
	bool m_prepared = false;
	RectifiedGeometry m_geometry;
	cv::Mat m_mapLeftX, m_mapLeftY, m_mapRightX, m_mapRightY;
	cv::Mat1b m_leftNotImaged, m_rightNotImaged;
};

/** Grey 8-bit view (or conversion) of an MRPT image. */
cv::Mat1b toGrey(const mrpt::img::CImage& image);

}  // namespace lvf::evaluation
