#include <lvfusion/common/IniSection.h>
#include <lvfusion/evaluation/ModelDisparity.h>
#include <lvfusion/fusion/CLaserStereoFusion.h>
#include <lvfusion/fusion/CalibrationEvidence.h>
#include <lvfusion/fusion/ModelWalls.h>

#include <lvfusion/common/InputError.h>
#include <lvfusion/common/LaserRange.h>
#include <mrpt/core/format.h>

#include <chrono>
#include <cmath>

IMPLEMENTS_MRPT_OBJECT(CLaserStereoFusion, mrpt::rtti::CObject, lvf::fusion)

namespace lvf::fusion
{
using lvf::common::writeOption;

namespace
{
const char* kLines = "ScanLineExtractor";
const char* kEvaluation = "ModelEvaluator";
const char* kDepth = "FocusedEpipolarSearch";
const char* kGrowth = "HorizontalSurfaceGrowth";
const char* kFusion = "ScanFusion";
const char* kMemory = "VisualPointMemory";

/** Runs f() and adds its duration to `ms`. */
template <typename F>
auto timed(double& ms, F&& f)
{
	const auto t0 = std::chrono::steady_clock::now();
	auto r = f();
	ms += std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
	return r;
}
}  // namespace

void CLaserStereoFusion::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::rejectUnknownSections(source, {section, kLines, kEvaluation, kDepth, kGrowth, kFusion, kMemory});
	lvf::common::rejectKeysOfOtherSections<TOptions>(source, section);
	lvf::common::IniSection ini(source, section);
	band.low = ini.real("obstacle_min_height", band.low, 0, 100);
	band.high = ini.real("robot_height", band.high, band.low, 100);
	visualFloorClearance = ini.real("visual_floor_clearance", visualFloorClearance, 0, band.high - band.low);
	floorHeight = ini.real("floor_height", floorHeight, -100, 100);
	facetStrayReturns = ini.flag("facet_stray_returns", facetStrayReturns);
	joinSegmentEnds = ini.real("join_segment_ends", joinSegmentEnds, 0, 10);
	minFloorAgreement = ini.real("min_floor_agreement", minFloorAgreement, 0, 1);
	maxInconsistentFraction = ini.real("max_inconsistent_fraction", maxInconsistentFraction, 0, 1);
	calibrationNcc = ini.real("calibration_ncc", calibrationNcc, -1, 1);
	evaluateSearchGridOnly = ini.flag("evaluate_search_grid_only", evaluateSearchGridOnly);
	rectifyAlpha = ini.real("rectify_alpha", rectifyAlpha, 0, 1);
	ini.rejectUnknownKeys();
	lines.loadFromConfigFile(source, kLines);
	evaluation.loadFromConfigFile(source, kEvaluation);
	depth.loadFromConfigFile(source, kDepth);
	growth.loadFromConfigFile(source, kGrowth);
	fusion.loadFromConfigFile(source, kFusion);
	memory.loadFromConfigFile(source, kMemory);
}

void CLaserStereoFusion::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "obstacle_min_height", band.low, "lower edge of the robot height band [m]");
	writeOption(c, s, "robot_height", band.high, "upper edge of the band: the robot's height [m]");
	writeOption(c, s, "visual_floor_clearance", visualFloorClearance, "a visual point must lie at least this far above obstacle_min_height: floor texture triangulated a centimetre high is no obstacle [m]");
	writeOption(c, s, "floor_height", floorHeight, "floor z in the robot frame [m]");
	writeOption(c, s, "facet_stray_returns", facetStrayReturns, "model returns that fit no line segment as narrow walls square to their rays");
	writeOption(c, s, "join_segment_ends", joinSegmentEnds, "join the ends of line segments on neighbouring rays at most this far apart by a wall (a corner the fit left open); 0: never [m]");
	writeOption(c, s, "min_floor_agreement", minFloorAgreement, "less of the model's visible floor consistent in the images than this share: calibration suspect, laser only [0..1]");
	writeOption(c, s, "max_inconsistent_fraction", maxInconsistentFraction, "more of all judged pixels inconsistent than this share: calibration suspect, laser only [0..1]");
	writeOption(c, s, "calibration_ncc", calibrationNcc, "for these two checks a judged pixel agrees with the model at this NCC or more (not the evaluation's ncc_threshold) [-1..1]");
	writeOption(c, s, "evaluate_search_grid_only", evaluateSearchGridOnly, "evaluate the model only at the pixels the depth search reads (its pixel_stride grid): same result there, faster");
	writeOption(c, s, "rectify_alpha", rectifyAlpha, "where the rig needs rectifying, how much of the views the rectified pair keeps (OpenCV stereoRectify's alpha): 0 only what both cameras imaged (the edges cropped), 1 all, with black corners left unjudged [0..1]");
	lines.saveToConfigFile(c, kLines);
	evaluation.saveToConfigFile(c, kEvaluation);
	depth.saveToConfigFile(c, kDepth);
	growth.saveToConfigFile(c, kGrowth);
	fusion.saveToConfigFile(c, kFusion);
	memory.saveToConfigFile(c, kMemory);
}

CLaserStereoFusion::CLaserStereoFusion() : CLaserStereoFusion(TOptions()) {}

CLaserStereoFusion::CLaserStereoFusion(const TOptions& options)
	: mrpt::system::COutputLogger("CLaserStereoFusion"),
	  m_options(options),
	  m_stereo(options.rectifyAlpha),
	  m_memory(options.memory)
{
}

size_t CLaserStereoFusion::Result::shortenedBearings(const mrpt::obs::CObservation2DRangeScan& laser) const
{
	size_t shortened = 0;
	for (size_t i = 0; i < laser.getScanSize() && fused && i < fused->getScanSize(); i++)
		shortened += fused->getScanRange(i) < lvf::laserRangeOrMax(laser, i);
	return shortened;
}

CLaserStereoFusion::Result CLaserStereoFusion::laserOnly(
	const mrpt::obs::CObservation2DRangeScan& scan, std::string why)
{
	Result r;
	r.fellBackToLaser = true;
	if (!why.empty()) r.warnings.push_back(std::move(why));
	r.visualRanges.assign(scan.getScanSize(), std::numeric_limits<float>::infinity());
	r.bridged.assign(scan.getScanSize(), false);
	r.fused = ScanFusion::fuse(scan, r.visualRanges);
	return r;
}

CLaserStereoFusion::Result CLaserStereoFusion::process(
	const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::obs::CObservationStereoImages& stereo,
	const std::string& record, const std::optional<mrpt::poses::CPose2D>& odometry)
{
	Result r = fuseFrame(scan, stereo, record, odometry);
	for (const auto& w : r.warnings) MRPT_LOG_WARN(w);
	// (MRPT's macro evaluates its arguments only when DEBUG is visible.)
	MRPT_LOG_DEBUG_FMT(
		"%s: %zu segments; %zu pixels inconsistent, %zu searched; %zu visual points (%zu grown, %zu "
		"remembered); %zu of %zu bearings nearer than the laser; %.2f ms%s",
		record.c_str(), r.segments.size(), r.evaluation.count(lvf::evaluation::PixelState::Inconsistent),
		r.search.stats.searchedPixels, r.search.points.size(), r.grownPoints, r.remembered.size(),
		r.shortenedBearings(scan), scan.getScanSize(), r.times.total(), r.fellBackToLaser ? " (laser only)" : "");
	return r;
}

namespace
{
/** A frame's scan as the stages may use it: ranges a driver should never
 * report (NaN, infinite, not positive) made invalid, said once in
 * `warning`. A scan no stage can use at all throws. */
struct CheckedScan
{
	mrpt::obs::CObservation2DRangeScan scan;
	size_t valid = 0;  //!< rays left with a return
	std::optional<std::string> warning;
};

CheckedScan checkedScan(const mrpt::obs::CObservation2DRangeScan& raw, const std::string& record)
{
	if (raw.getScanSize() == 0) throw lvf::common::InputError(record, "scan " + raw.sensorLabel, "has no rays");
	// The bearings are spread over the aperture: without one, every stage's
	// ray index would divide by zero.
	if (raw.getScanSize() > 1 && !(std::isfinite(raw.aperture) && raw.aperture > 0))
		throw lvf::common::InputError(
			record, "scan " + raw.sensorLabel,
			mrpt::format("aperture %g rad: must be positive and finite", static_cast<double>(raw.aperture)));
	CheckedScan out{raw, 0, std::nullopt};
	auto& scan = out.scan;
	size_t bad = 0;
	for (size_t i = 0; i < scan.getScanSize(); i++)
	{
		const float range = scan.getScanRange(i);
		if (scan.getScanRangeValidity(i) && !(std::isfinite(range) && range > 0))
		{
			scan.setScanRangeValidity(i, false);
			scan.setScanRange(i, scan.maxRange);
			bad++;
		}
		out.valid += scan.getScanRangeValidity(i);
	}
	if (bad)
		out.warning = record + ": scan " + scan.sensorLabel + ": " + std::to_string(bad) +
			" rays with NaN, infinite or non-positive range, treated as no return";
	return out;
}
}  // namespace

CLaserStereoFusion::Result CLaserStereoFusion::fuseFrame(
	const mrpt::obs::CObservation2DRangeScan& rawScan,
	const mrpt::obs::CObservationStereoImages& stereo, const std::string& record,
	const std::optional<mrpt::poses::CPose2D>& odometry)
{
	const CheckedScan checked = checkedScan(rawScan, record);
	const auto& scan = checked.scan;
	std::vector<std::string> warnings;
	if (checked.warning) warnings.push_back(*checked.warning);
	if (checked.valid == 0)
	{
		Result r = laserOnly(scan, record + ": scan " + scan.sensorLabel +
			" has no valid range: no model to check, laser only");
		r.warnings.insert(r.warnings.begin(), warnings.begin(), warnings.end());
		return r;
	}

	Result r;
	r.warnings = warnings;
	m_stereo.prepare(stereo, record);
	r.geometry = m_stereo.geometry();
	r.rectified = m_stereo.remaps();

	r.segments = timed(r.times.lines, [&] {
		return lvf::lines::ScanLineExtractor(m_options.lines).extract(scan);
	});
	const cv::Mat1f modelDisparity = timed(r.times.model, [&] {
		r.model = lvf::model::PlanarSceneModel(
			modelWalls(scan, r.segments, m_options.facetStrayReturns, m_options.joinSegmentEnds), m_options.floorHeight);
		return lvf::evaluation::renderModelDisparity(r.model, r.geometry);
	});
	// Where rectification resampled the pair, the evaluation takes the
	// cameras' noise as taken and leaves out what they did not image.
	const lvf::evaluation::RectificationEffects rectification =
		timed(r.times.rectify, [&] { return m_stereo.rectify(stereo, r.left, r.right); });
	const lvf::evaluation::ModelEvaluator evaluator(m_options.evaluation);
	// The search's grid starts half a window from the border.
	const int gridFirst = m_options.evaluateSearchGridOnly ? m_options.evaluation.windowSize / 2 : 0;
	const int gridStride = m_options.evaluateSearchGridOnly ? m_options.depth.pixelStride : 1;
	r.evaluation = timed(r.times.evaluate, [&] {
		return m_options.evaluateSearchGridOnly
			? evaluator.evaluateGrid(r.left, r.right, modelDisparity, r.geometry, gridFirst, gridStride, rectification)
			: evaluator.evaluate(r.left, r.right, modelDisparity, r.geometry, rectification);
	});
	if (auto suspect = calibrationSuspect(r, record)) return laserOnlyAfterTheCheck(scan, std::move(r), *suspect);

	r.search = timed(r.times.search, [&] {
		auto found = lvf::depth::FocusedEpipolarSearch(m_options.depth)
			.search(r.left, r.right, r.evaluation, m_options.evaluation.windowSize, r.geometry, m_options.visualBand(),
				m_options.floorHeight);
		r.grownPoints = lvf::depth::HorizontalSurfaceGrowth(m_options.growth)
			.grow(r.left, r.right, r.geometry, r.evaluation, m_options.visualBand(),
				m_options.depth.textureGate(r.evaluation.noiseStd), m_options.depth.pixelStride, found.points);
		return found;
	});
	r.fused = timed(r.times.fuse, [&] { return fusedScan(scan, odometry, rectification, r); });
	return r;
}

std::optional<std::string> CLaserStereoFusion::calibrationSuspect(Result& r, const std::string& record) const
{
	// Every judged pixel: the whole image, or the search grid (timed with
	// the model check it reads).
	const CalibrationEvidence evidence = timed(r.times.evaluate, [&] {
		return calibrationEvidence(r.geometry, r.evaluation, m_options.floorHeight, m_options.calibrationNcc);
	});
	const double floorAgreement = evidence.floorAgreement(), inconsistent = evidence.disagreeingShare();
	const bool floorJudgeable = evidence.floorJudged >= TOptions::kMinJudgedFloorPixels;
	const bool floorContradicted = floorJudgeable && floorAgreement < m_options.minFloorAgreement;
	if (!floorContradicted && inconsistent <= m_options.maxInconsistentFraction) return std::nullopt;
	// Too few floor pixels are no evidence (and none at all reads as 100%
	// agreeing): say so, rather than give their share.
	const std::string floor = floorJudgeable ? std::to_string(int(100 * floorAgreement)) + "% of the floor consistent"
											 : "too little floor in view to judge";
	return record + ": the images contradict the laser model (" + floor + ", " +
		std::to_string(int(100 * inconsistent)) +
		"% of the judged pixels inconsistent): stereo calibration suspect, laser only";
}

CLaserStereoFusion::Result CLaserStereoFusion::laserOnlyAfterTheCheck(
	const mrpt::obs::CObservation2DRangeScan& scan, Result&& checked, const std::string& why)
{
	Result fallback = laserOnly(scan, why);
	fallback.warnings.insert(fallback.warnings.begin(), checked.warnings.begin(), checked.warnings.end());
	fallback.segments = std::move(checked.segments);
	fallback.model = std::move(checked.model);
	fallback.geometry = checked.geometry;
	fallback.rectified = checked.rectified;
	fallback.left = checked.left;
	fallback.right = checked.right;
	fallback.evaluation = std::move(checked.evaluation);
	fallback.times = checked.times;
	return fallback;
}

mrpt::obs::CObservation2DRangeScan::Ptr CLaserStereoFusion::fusedScan(
	const mrpt::obs::CObservation2DRangeScan& scan, const std::optional<mrpt::poses::CPose2D>& odometry,
	const lvf::evaluation::RectificationEffects& rectification, Result& r)
{
	const std::vector<lvf::depth::VisualPoint>* points = &r.search.points;
	std::vector<lvf::depth::VisualPoint> withRemembered;
	if (m_memory.enabled() && odometry)
	{
		// The searched image: the columns the search's points can lie at,
		// the rows and right-image columns where its window fits.
		const int half = m_options.evaluation.windowSize / 2;
		const float lastRow = float(r.geometry.size.height - 1 - half);
		const float lastRightColumn = float(r.geometry.size.width - 1 - half);
		r.remembered = m_memory.recall(*odometry, r.geometry,
			{r.search.firstColumn, r.search.lastColumn, float(half), lastRow, m_options.depth.zMin,
				m_options.depth.zMax, float(half), lastRightColumn, rectification.leftNotImaged,
				rectification.rightNotImaged});
		m_memory.remember(r.search.points);
		withRemembered = r.search.points;
		withRemembered.insert(withRemembered.end(), r.remembered.begin(), r.remembered.end());
		points = &withRemembered;
	}
	const ScanFusion fusion(m_options.fusion);
	r.visualRanges = fusion.visualRanges(scan, *points,
		ScanFusion::SearchedColumns{r.search.firstColumn, r.search.lastColumn, float(m_options.depth.pixelStride)},
		&r.bridged);
	return ScanFusion::fuse(scan, r.visualRanges);
}

}  // namespace lvf::fusion
