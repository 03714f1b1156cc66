#pragma once
// A calibrated stereo pair rendered by CPU ray casting: Lambertian shading
// with ambient light, per-camera gain and Gaussian noise, lens distortion as
// stored in the calibration. Deterministic for a given seed, headless.

#include <lvfusion/simulation/CameraRayTable.h>
#include <lvfusion/simulation/WorldGeometry.h>
#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/img/TStereoCamera.h>
#include <mrpt/obs/CObservationStereoImages.h>
#include <mrpt/poses/CPose3D.h>
#include <opencv2/core.hpp>

#include <memory>

namespace lvf::simulation
{
class SimulatedStereoRig
{
   public:
	/** INI section [SimulatedStereoRig]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		int ncols = 640, nrows = 480;  //!< image size [px]
		double fx = 450, fy = 450;	//!< focal lengths [px]
		double cx = 319.5, cy = 239.5;	//!< principal point [px]
		/** plumb_bob distortion [k1 k2 p1 p2 k3], or 8 values with k4 k5 k6
		 * (OpenCV's rational model); all zero: none. */
		std::vector<double> dist{0, 0, 0, 0, 0};
		double baseline = 0.12;	 //!< right camera is this far to the right [m]
		/** Right camera's rotation relative to the left [deg]: zero for a
		 * parallel rig; small values model a rig that needs rectifying. */
		double rightYawDeg = 0, rightPitchDeg = 0, rightRollDeg = 0;
		/** Left camera position on the robot [m]. */
		double poseX = 0.10, poseY = 0.06, poseZ = 1.00;
		double panDeg = 0;	//!< left (+) / right (-) of the robot's heading [deg]
		double tiltDeg = 15;	 //!< looking down (+) [deg]
		double leftGain = 1.0, rightGain = 0.95;  //!< intensity gain
		double leftNoiseStd = 2.0, rightNoiseStd = 2.0;	 //!< [grey levels]
		int supersampling = 1;	//!< samples per pixel per axis (odd), anti-aliasing

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;

		/** The calibration this rig's images obey. */
		mrpt::img::TStereoCamera stereoCamera() const;
		/** Left camera relative to the robot, MRPT camera axes. */
		mrpt::poses::CPose3D leftCameraPose() const;
		/** Right camera relative to the left one (rightCameraPose). */
		mrpt::poses::CPose3D rightCameraPose() const;
	};

	explicit SimulatedStereoRig(const TOptions& options);

	struct Images
	{
		cv::Mat1b left, right;
		cv::Mat1f leftDepth;  //!< z in the left camera [m], inf: nothing; if asked
	};
	/** Renders both cameras with the robot at `robotPose` (world frame). */
	Images render(
		const WorldGeometry& world, const mrpt::poses::CPose3D& robotPose,
		uint64_t noiseSeed, bool withDepth) const;

	/** Fills a CObservationStereoImages (label STEREO) with images and the
	 * full calibration. */
	mrpt::obs::CObservationStereoImages::Ptr toObservation(
		const Images& images, mrpt::Clock::time_point stamp) const;

	const TOptions& options() const { return m_options; }

	/** Renders one camera; exposed for tests and benchmarks. The brute-force
	 * variant tests every box at every sample (the reference for culling). */
	void renderCamera(
		const WorldGeometry& world, const mrpt::poses::CPose3D& cameraPose,
		const CameraRayTable& rays, double gain, double noiseStd,
		uint64_t noiseSeed, cv::Mat1b& image, cv::Mat1f* depth,
		bool bruteForce = false) const;

	const CameraRayTable& leftRays() const { return *m_leftRays; }
	const CameraRayTable& rightRays() const { return *m_rightRays; }

   private:
	TOptions m_options;
	mrpt::img::TStereoCamera m_calibration;
	std::unique_ptr<CameraRayTable> m_leftRays, m_rightRays;
};

}  // namespace lvf::simulation
