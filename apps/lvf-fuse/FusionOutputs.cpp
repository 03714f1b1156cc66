#include "FusionOutputs.h"

#include <lvfusion/common/GridInsertion.h>
#include <lvfusion/common/GridOutputs.h>
#include <lvfusion/common/ObservationLabels.h>
#include <lvfusion/evaluation/ModelEvaluator.h>
#include <mrpt/core/format.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>

namespace lvf::apps
{
using lvf::evaluation::PixelState;

mrpt::obs::CObservationImage::Ptr evaluationImage(
	const lvf::fusion::CLaserStereoFusion::Result& r, mrpt::Clock::time_point stamp)
{
	cv::Mat3b picture = lvf::evaluation::drawEvaluationOverlay(r.left, r.evaluation);
	// Searched and rejected (weak, ambiguous, ...): orange; found: yellow.
	// Pixels left alone because something nearer was found on their
	// bearing (nearest first) keep the model check's colour.
	using lvf::depth::SearchOutcome;
	if (!r.search.outcome.empty())
		for (int v = 0; v < picture.rows; v++)
			for (int u = 0; u < picture.cols; u++)
			{
				const auto o = static_cast<SearchOutcome>(r.search.outcome(v, u));
				if (o != SearchOutcome::NotSearched && o != SearchOutcome::BehindNearer && o != SearchOutcome::Accepted)
					picture(v, u) = {0, 140, 255};
			}
	for (const auto& p : r.search.points)
		cv::circle(picture, cv::Point(cvRound(p.u), cvRound(p.v)), 1, {0, 255, 255}, cv::FILLED);
	auto obs = std::make_shared<mrpt::obs::CObservationImage>();
	obs->sensorLabel = lvf::common::kEvaluationImageLabel;
	obs->timestamp = stamp;
	obs->image = mrpt::img::CImage(picture, mrpt::img::DEEP_COPY);
	obs->cameraPose = r.geometry.leftPose;
	obs->cameraParams.ncols = static_cast<uint32_t>(r.geometry.size.width);
	obs->cameraParams.nrows = static_cast<uint32_t>(r.geometry.size.height);
	obs->cameraParams.setIntrinsicParamsFromValues(r.geometry.f, r.geometry.f, r.geometry.cx, r.geometry.cy);
	return obs;
}

// The grids start 10 m square round the odometry's origin and grow to take
// in every scan inserted (MRPT grows them; GridInsertion.h bounds by how
// much), so a long run is whole.
constexpr float kInitialGridHalfSide = 5;  // [m]

FusionOutputs::FusionOutputs(
	lvf::common::StagedOutputFiles& files, const std::string& name, double gridResolution, bool writePoints)
	: m_files(files),
	  m_name(name),
	  m_laserGrid(-kInitialGridHalfSide, kInitialGridHalfSide, -kInitialGridHalfSide, kInitialGridHalfSide,
				  static_cast<float>(gridResolution)),
	  m_fusedGrid(-kInitialGridHalfSide, kInitialGridHalfSide, -kInitialGridHalfSide, kInitialGridHalfSide,
				  static_cast<float>(gridResolution))
{
	m_csv.open(files.stage(name + "_frames.csv"));
	m_csv << "frame,timestamp,segments,noise_std,texture_gate,inconsistent_px,unmodelled_px,untextured_px,searched_px,ncc_evaluations,"
			 "visual_points,grown_points,remembered_points,shortened_bearings,bridged_bearings,fell_back,t_lines_ms,t_model_ms,t_rectify_ms,"
			 "t_evaluate_ms,t_search_ms,t_fuse_ms,t_total_ms,in_view,hidden,recall,phantom_rate,"
			 "hidden_range_error_m,seen_hidden,seen_recall\n";
	m_bearingsCsv.open(files.stage(name + "_bearings.csv"));
	m_bearingsCsv << "frame,ray,bearing_deg,laser_m,visual_m,fused_m,truth_m,in_view,hidden,bridged,seen_truth_m,"
					 "counted_in_view,counted_hidden,recalled,phantom\n";
	if (writePoints)
	{
		m_pointsCsv.open(files.stage(name + "_points.csv"));
		// Pixel and disparity in the rectified left image (none for a
		// remembered point); position in the robot frame; bearing and
		// horizontal range from the laser, in its frame, as the fused scan
		// bins the points (the bearings CSV's bearing_deg).
		m_pointsCsv << "frame,source,u,v,disparity_px,ncc,x_m,y_m,z_m,bearing_deg,range_m\n";
	}
}

namespace
{
/** A range for the CSV: empty where there is none (no return, no point). */
std::string rangeField(float range, bool valid = true)
{
	return valid && std::isfinite(range) ? mrpt::format("%.3f", range) : std::string();
}
}  // namespace

void FusionOutputs::addBearings(
	size_t frame, const mrpt::obs::CObservation2DRangeScan& laser,
	const lvf::fusion::CLaserStereoFusion::Result& r, const std::optional<FrameTruth>& truth)
{
	for (size_t i = 0; i < laser.getScanSize(); i++)
	{
		m_bearingsCsv << frame << ',' << i << ',' << mrpt::format("%.2f", mrpt::RAD2DEG(laser.getScanAngle(i))) << ','
					  << rangeField(laser.getScanRange(i), laser.getScanRangeValidity(i)) << ','
					  << rangeField(i < r.visualRanges.size() ? r.visualRanges[i] : INFINITY) << ','
					  << rangeField(r.fused->getScanRange(i), r.fused->getScanRangeValidity(i)) << ',';
		if (truth)
			m_bearingsCsv << rangeField(truth->ranges[i]) << ',' << int(truth->inView[i]) << ','
						  << int(truth->hidden[i]);
		else
			m_bearingsCsv << ",,";
		m_bearingsCsv << ',' << int(i < r.bridged.size() && r.bridged[i]) << ','
					  << (truth && !truth->seenRanges.empty() ? rangeField(truth->seenRanges[i]) : std::string()) << ',';
		if (truth)
		{
			const auto& v = truth->verdicts[i];
			m_bearingsCsv << int(v.scored) << ',' << int(v.hidden) << ',' << int(v.recalled) << ',' << int(v.phantom);
		}
		else
			m_bearingsCsv << ",,,";
		m_bearingsCsv << '\n';
	}
}

void FusionOutputs::addPoints(
	size_t frame, const mrpt::obs::CObservation2DRangeScan& laser, const lvf::fusion::CLaserStereoFusion::Result& r)
{
	auto write = [&](const lvf::depth::VisualPoint& p, const char* source) {
		double lx, ly, lz;
		laser.sensorPose.inverseComposePoint(p.robot.x(), p.robot.y(), p.robot.z(), lx, ly, lz);
		if (std::isfinite(p.u))
			m_pointsCsv << mrpt::format("%zu,%s,%.0f,%.0f,%.3f,%.3f,", frame, source, p.u, p.v, p.disparity, p.ncc);
		else
			m_pointsCsv << frame << ',' << source << ",,,,,";
		m_pointsCsv << mrpt::format("%.3f,%.3f,%.3f,%.2f,%.3f\n", p.robot.x(), p.robot.y(), p.robot.z(),
			mrpt::RAD2DEG(std::atan2(ly, lx)), std::hypot(lx, ly));
	};
	// HorizontalSurfaceGrowth appends its points after the search's.
	const size_t searched = r.search.points.size() - r.grownPoints;
	for (size_t k = 0; k < r.search.points.size(); k++) write(r.search.points[k], k < searched ? "search" : "grown");
	for (const auto& p : r.remembered) write(p, "remembered");
}

bool FusionOutputs::add(
	size_t frame, const mrpt::obs::CObservation2DRangeScan& laser,
	const lvf::fusion::CLaserStereoFusion::Result& r, const mrpt::poses::CPose2D& odometry,
	const std::optional<FrameTruth>& truth)
{
	const bool inserted = lvf::common::insertScansAt(
		odometry, m_inserted == 0, {{&m_laserGrid, &laser}, {&m_fusedGrid, r.fused.get()}});
	m_inserted += inserted;

	const size_t shortened = r.shortenedBearings(laser);
	const auto bridged = static_cast<size_t>(std::count(r.bridged.begin(), r.bridged.end(), true));
	const auto& t = r.times;
	m_csv << mrpt::format(
		"%zu,%.6f,%zu,%.2f,%.2f,%zu,%zu,%zu,%zu,%zu,%zu,%zu,%zu,%zu,%zu,%d,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f,%.3f", frame,
		mrpt::Clock::toDouble(laser.timestamp), r.segments.size(), r.evaluation.noiseStd, r.evaluation.textureGate,
		r.evaluation.count(PixelState::Inconsistent), r.evaluation.count(PixelState::Unmodelled),
		r.evaluation.count(PixelState::Untextured),
		r.search.stats.searchedPixels, r.search.stats.disparitiesTested, r.search.points.size(),
		r.grownPoints, r.remembered.size(), shortened, bridged, r.fellBackToLaser ? 1 : 0, t.lines, t.model, t.rectify, t.evaluate, t.search,
		t.fuse, t.total());
	if (truth)
	{
		const auto& s = truth->score;
		m_csv << mrpt::format(
			",%zu,%zu,%.4f,%.4f,%.4f", s.inView, s.hidden, s.recall(), s.phantomRate(), s.hiddenRangeErrorMedian());
		m_csv << (truth->seenRanges.empty() ? std::string(",,\n") : mrpt::format(",%zu,%.4f\n", s.seenHidden, s.seenRecall()));
	}
	else
		m_csv << ",,,,,,,\n";
	addBearings(frame, laser, r, truth);
	if (m_pointsCsv.is_open()) addPoints(frame, laser, r);
	return inserted;
}

void FusionOutputs::close()
{
	m_csv.close();
	m_bearingsCsv.close();
	if (m_pointsCsv.is_open()) m_pointsCsv.close();
	lvf::common::saveGrid(m_laserGrid, m_files.stage(m_name + "_laser.gridmap.gz"));
	lvf::common::saveGrid(m_fusedGrid, m_files.stage(m_name + "_fused.gridmap.gz"));
	std::vector<cv::Mat> pictures;
	for (const auto& grid : lvf::common::onCommonExtent({&m_laserGrid, &m_fusedGrid}))
	{
		mrpt::img::CImage img;
		grid.getAsImage(img, false, true);	// north up
		pictures.push_back(img.asCvMat<cv::Mat>(mrpt::img::DEEP_COPY));
	}
	lvf::common::writeImage(m_files.stage(m_name + "_grids.png"),
		lvf::common::sideBySide(pictures, {"laser only", "laser + vision"}));
}

}  // namespace lvf::apps
