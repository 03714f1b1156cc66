#pragma once
// The whole simulated robot: a world, a 2D laser, a stereo rig and odometry,
// stepping along the world's path. Registered with MRPT's class registry
// (found by name as "CStereoLaserSimulator" once the plugin is loaded).
//
// Its configuration is an MRPT-style INI file with one section per part:
//   [CStereoLaserSimulator] [SimulatedLaser] [SimulatedStereoRig] [SimulatedOdometry]
// (defaults and meanings: share/lvfusion/config/sensors.ini, or --dump-config).

#include <lvfusion/simulation/SimulatedLaser.h>
#include <lvfusion/simulation/SimulatedOdometry.h>
#include <lvfusion/simulation/SimulatedStereoRig.h>
#include <lvfusion/simulation/StereoSeenTruth.h>
#include <lvfusion/simulation/World.h>
#include <lvfusion/simulation/WorldGeometry.h>
#include <mrpt/rtti/CObject.h>

#include <memory>

namespace lvf::simulation
{
class CStereoLaserSimulator : public mrpt::rtti::CObject
{
	DEFINE_MRPT_OBJECT(CStereoLaserSimulator, lvf::simulation)

   public:
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		uint32_t seed = 1;	//!< all noise derives from it (frame-wise)
		double framePeriod = 0.2;  //!< time between frames [s]
		double stereoDelay = 0.005;	 //!< camera timestamp after the laser's [s]
		double startTime = 1.7e9;  //!< timestamp of frame 0 [s since 1970]
		SimulatedLaser::TOptions laser;
		SimulatedStereoRig::TOptions stereo;
		SimulatedOdometry::TOptions odometry;

		/** Reads every section; `section` names this class's own. Unknown
		 * sections and keys are errors. */
		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source,
			const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target,
			const std::string& section) const override;
	};

	CStereoLaserSimulator() = default;
	CStereoLaserSimulator(World world, const TOptions& options);

	struct Frame
	{
		size_t index = 0;
		mrpt::Clock::time_point timestamp;
		mrpt::poses::CPose2D truePose;
		mrpt::poses::CPose2D odometry;	//!< noisy dead reckoning
		mrpt::obs::CObservation2DRangeScan::Ptr scan;
		mrpt::obs::CObservationStereoImages::Ptr stereo;
		std::vector<float> truthScan;  //!< per laser bearing, inf: nothing
		cv::Mat1f leftDepth;  //!< when asked for: z in the left camera [m]
		/** With the depth: the truth scan of what both cameras see
		 * (StereoSeenTruth.h), inf: nothing seen. */
		std::vector<float> seenTruthScan;
	};

	size_t frameCount() const { return m_world ? m_world->path.size() : 0; }
	/** Frames must be simulated in order (odometry accumulates). */
	Frame simulateNextFrame(bool withDepth);
	/** The sensors at an arbitrary true pose and time (closed-loop runs,
	 * where the path is not known in advance). `index` seeds the frame's
	 * noise; odometry accumulates over calls, so call in time order.
	 * `withStereo` false skips the cameras (laser-only runs), `withDepth`
	 * also returns the left camera's depth. */
	Frame simulateAt(
		size_t index, const mrpt::poses::CPose2D& truePose, double time,
		bool withStereo, bool withDepth);

	const World& world() const { return *m_world; }
	const TOptions& options() const { return m_options; }
	const WorldGeometry& geometry() const { return *m_geometry; }
	const SimulatedStereoRig& stereoRig() const { return *m_stereo; }
	const SimulatedLaser& laser() const { return *m_laser; }

   private:
	TOptions m_options;
	std::shared_ptr<const World> m_world;
	std::shared_ptr<const WorldGeometry> m_geometry;
	std::shared_ptr<const SimulatedLaser> m_laser;
	std::shared_ptr<const SimulatedStereoRig> m_stereo;
	std::shared_ptr<SimulatedOdometry> m_odometry;
	std::shared_ptr<const StereoSeenTruth> m_seenTruth;	 //!< made by the first frame with depth
	size_t m_nextFrame = 0;
};

}  // namespace lvf::simulation
