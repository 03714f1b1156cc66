#pragma once
// The paper's whole perception pipeline as one MRPT-registered class: a 2D
// scan and a stereo pair in, every stage's result out.
//
//   1. scan -> line segments              lvf::lines::ScanLineExtractor
//   2. segments -> planar model           lvf::model::PlanarSceneModel
//   3. model evaluation (NCC)             lvf::evaluation::ModelEvaluator
//   4. focused epipolar depth search      lvf::depth::FocusedEpipolarSearch
//      horizontal surfaces followed on    lvf::depth::HorizontalSurfaceGrowth
//   5. fused virtual scan                 lvf::fusion::ScanFusion
//      with earlier frames' points           lvf::fusion::VisualPointMemory
//
// Configuration: an MRPT INI file with one section per stage (defaults and
// meanings in share/lvfusion/config/fusion.ini, or lvf-fuse --dump-config).
// Messages: an MRPT COutputLogger ("CLaserStereoFusion"), as MRPT's own
// classes are: a frame's warnings at WARN (on the console unless told
// otherwise), its figures -- segments, pixels, points, bearings, time -- at
// DEBUG. Result::warnings holds the same warnings for the program itself.

#include <lvfusion/common/HeightBand.h>
#include <lvfusion/depth/FocusedEpipolarSearch.h>
#include <lvfusion/depth/HorizontalSurfaceGrowth.h>
#include <lvfusion/evaluation/ModelEvaluator.h>
#include <lvfusion/evaluation/RectifiedStereo.h>
#include <lvfusion/fusion/ScanFusion.h>
#include <lvfusion/fusion/VisualPointMemory.h>
#include <lvfusion/lines/ScanLineExtractor.h>
#include <lvfusion/model/PlanarSceneModel.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/system/COutputLogger.h>

#include <optional>

namespace lvf::fusion
{
class CLaserStereoFusion : public mrpt::rtti::CObject, public mrpt::system::COutputLogger
{
	DEFINE_MRPT_OBJECT(CLaserStereoFusion, lvf::fusion)

   public:
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		HeightBand band;  //!< obstacle_min_height .. robot_height [m]
		/** A visual point must lie at least this far above the band's lower
		 * edge [m]: floor texture triangulated a centimetre high (a floor
		 * fitted to within its few millimetres, a disparity a tenth of a pixel
		 * off) is no obstacle 5 cm tall. Measured: Middlebury Recycle's four
		 * phantom bearings, points 0.051-0.063 m up in front of a bin, gone,
		 * its recall and the seeded rooms' as they were (measurements.md). */
		double visualFloorClearance = 0.01;
		/** The heights vision may report obstacles at: the band, less the
		 * clearance at its floor side. */
		HeightBand visualBand() const { return {band.low + visualFloorClearance, band.high}; }
		double floorHeight = 0;	 //!< floor z in the robot frame [m]
		bool facetStrayReturns = true;	//!< see ModelWalls.h
		/** Join the ends of segments on neighbouring rays that lie at most
		 * this far apart (ModelWalls.h) [m]; 0: never. */
		double joinSegmentEnds = 0.15;
		/** The calibration (not the world) is taken to be wrong, and the
		 * frame falls back to the laser, when less than this share of the
		 * model's floor looks consistent in the images (CalibrationEvidence.h;
		 * measured: 0.01 with a wrong baseline; 0.75-0.95 on simulated rooms,
		 * 0.33 and 0.73 on the Middlebury floors, whose cluttered scenes the
		 * floor-and-walls model explains only roughly)... */
		double minFloorAgreement = 0.2;
		/** ...or more than this share of all judged pixels is inconsistent
		 * (for frames without a judged floor; measured 0.99 with a wrong
		 * baseline, at most 0.77 on the samples, random rooms and Middlebury). */
		double maxInconsistentFraction = 0.95;
		/** For both checks a judged pixel agrees with the model at this NCC
		 * or more (CalibrationEvidence.h): the fractions above were measured so,
		 * whatever the evaluation's own threshold, which decides where to
		 * search (had the checks used the evaluation's at 0.95, Middlebury
		 * Recycle's floor would agree at 0.17 and the scene fall back to the
		 * laser). */
		double calibrationNcc = 0.9;
		/** Sampled floor pixels needed to judge the floor at all. */
		static constexpr size_t kMinJudgedFloorPixels = 100;
		/** Evaluate the model only at the pixels the depth search reads
		 * (its pixel_stride grid): the same judgement there, several times
		 * cheaper; the evaluation overlay then shows only those pixels, and
		 * the fraction above is taken over them. */
		bool evaluateSearchGridOnly = true;
		/** Where the rig needs rectifying, how much of the cameras' views the
		 * rectified pair keeps (OpenCV stereoRectify's alpha): 0 only what
		 * both imaged, cropping the view's edges (a lens's most), 1 all of
		 * it, with black corners the evaluation leaves out (README). */
		double rectifyAlpha = 0.25;
		lvf::lines::ScanLineExtractor::TOptions lines;
		lvf::evaluation::ModelEvaluator::TOptions evaluation;
		lvf::depth::FocusedEpipolarSearch::TOptions depth;
		lvf::depth::HorizontalSurfaceGrowth::TOptions growth;
		ScanFusion::TOptions fusion;
		VisualPointMemory::TOptions memory;

		/** Reads every section; unknown sections and keys are errors. */
		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	/** Milliseconds spent per stage. */
	struct StageTimes
	{
		double lines = 0, model = 0, rectify = 0, evaluate = 0, search = 0, fuse = 0;
		double total() const { return lines + model + rectify + evaluate + search + fuse; }
	};

	struct Result
	{
		std::vector<lvf::lines::LineSegment> segments;
		lvf::model::PlanarSceneModel model;
		lvf::evaluation::RectifiedGeometry geometry;
		/** The pair was resampled into that geometry (a lens, or cameras
		 * not parallel); false: used as it came. */
		bool rectified = false;
		cv::Mat1b left, right;	//!< rectified grey images
		lvf::evaluation::ModelEvaluation evaluation;
		lvf::depth::FocusedEpipolarSearch::Result search;  //!< its points include the grown ones
		size_t grownPoints = 0;	 //!< of them, added by HorizontalSurfaceGrowth
		/** Earlier frames' points where this frame's search could not look
		 * (VisualPointMemory), in this frame's robot frame; fused as well. */
		std::vector<lvf::depth::VisualPoint> remembered;
		std::vector<float> visualRanges;  //!< per laser bearing, inf: none
		/** Per laser bearing: its visual range closes a narrow gap between
		 * two found ones (ScanFusion's bridge_width), it was not measured. */
		std::vector<bool> bridged;
		mrpt::obs::CObservation2DRangeScan::Ptr fused;	//!< label FUSED
		bool fellBackToLaser = false;  //!< vision not used this frame (see warnings)
		std::vector<std::string> warnings;	//!< one line each, naming the record
		StageTimes times;

		/** Bearings where the fused scan is nearer than `laser` (the scan
		 * it was fused from) says: what vision added. */
		size_t shortenedBearings(const mrpt::obs::CObservation2DRangeScan& laser) const;
	};

	CLaserStereoFusion();
	explicit CLaserStereoFusion(const TOptions& options);

	/** @param record names the frame in messages ("log.rawlog: frame 12").
	 * Throws lvf::common::InputError for an unusable observation (no right
	 * image, sizes that disagree with the calibration, bad focal length, a
	 * scan without rays). Recoverable oddities (NaN/inf/negative ranges, no
	 * valid range, a calibration the images contradict) become warnings, and
	 * where vision cannot be trusted the frame falls back to the laser.
	 * @param odometry the robot's pose by odometry at the scan, for the
	 * memory of earlier frames' points ([VisualPointMemory]); without it,
	 * or with the memory off, each frame stands alone. Frames must come in
	 * time order while the memory is on. */
	Result process(
		const mrpt::obs::CObservation2DRangeScan& scan,
		const mrpt::obs::CObservationStereoImages& stereo, const std::string& record,
		const std::optional<mrpt::poses::CPose2D>& odometry = std::nullopt);

	const TOptions& options() const { return m_options; }

	/** The laser alone, for a frame vision cannot serve. */
	static Result laserOnly(const mrpt::obs::CObservation2DRangeScan& scan, std::string why);

   private:
	/** process() without its messages. */
	Result fuseFrame(
		const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::obs::CObservationStereoImages& stereo,
		const std::string& record, const std::optional<mrpt::poses::CPose2D>& odometry);
	/** The calibration check on a frame's model evaluation (its time added
	 * to the evaluation's): why the frame must fall back to the laser, or
	 * none. */
	std::optional<std::string> calibrationSuspect(Result& r, const std::string& record) const;
	/** The laser alone after the check failed, keeping what led to it
	 * (segments, model, images, evaluation, times) for the pictures. */
	static Result laserOnlyAfterTheCheck(
		const mrpt::obs::CObservation2DRangeScan& scan, Result&& checked, const std::string& why);
	/** Stage 5: the visual ranges of the search's points, with the memory's
	 * where the cameras cannot look now, and the fused scan. */
	mrpt::obs::CObservation2DRangeScan::Ptr fusedScan(
		const mrpt::obs::CObservation2DRangeScan& scan, const std::optional<mrpt::poses::CPose2D>& odometry,
		const lvf::evaluation::RectificationEffects& rectification, Result& r);

	TOptions m_options;
	lvf::evaluation::RectifiedStereo m_stereo;	// caches rectification maps
	VisualPointMemory m_memory;
};

}  // namespace lvf::fusion
