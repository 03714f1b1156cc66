#include <lvfusion/common/IniSection.h>
#include <lvfusion/lines/LineFit.h>
#include <lvfusion/lines/ScanLineExtractor.h>

#include "PieceBuilder.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lvf::lines
{
using lvf::common::writeOption;

ScanLineExtractor::TOptions ScanLineExtractor::TOptions::withRangeNoise(
	double rangeStd) const
{
	TOptions o = *this;
	o.splitDistance = std::max(3.0 * rangeStd, 0.01);
	o.mergeResidual = std::max(1.5 * rangeStd, 0.005);
	o.minInfluenceRadius = std::max(2.0 * rangeStd, 0.01);
	return o;
}

void ScanLineExtractor::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	noiseFromScan = ini.flag("noise_from_scan", noiseFromScan);
	maxGap = ini.real("max_gap", maxGap, 0.01, 100);
	minInfluenceRadius = ini.real("min_influence_radius", minInfluenceRadius, 0, 10);
	influenceWindow = ini.integer("influence_window", influenceWindow, 1, 50);
	splitDistance = ini.real("split_distance", splitDistance, 1e-3, 10);
	mergeResidual = ini.real("merge_residual", mergeResidual, 0, 10);
	mergeAngleDeg = ini.real("merge_angle_deg", mergeAngleDeg, 0, 90);
	mergeGap = ini.real("merge_gap", mergeGap, 0, 100);
	minPoints = ini.integer("min_points", minPoints, 2, 100000);
	minLength = ini.real("min_length", minLength, 0, 100);
	ini.rejectUnknownKeys();
}

void ScanLineExtractor::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "noise_from_scan", noiseFromScan, "min_influence_radius, split_distance and merge_residual from each scan's stated range noise (its stdError): 2x, 3x, 1.5x it; the values below only for scans that state none");
	writeOption(c, s, "max_gap", maxGap, "cut sphere-of-influence edges longer than this: always separate clusters [m]");
	writeOption(c, s, "min_influence_radius", minInfluenceRadius, "radius of influence at least this, ~2x range noise (see noise_from_scan) [m]");
	writeOption(c, s, "influence_window", influenceWindow, "neighbours searched on each side, in scan order, for radii and edges [points]");
	writeOption(c, s, "split_distance", splitDistance, "IEPF: split where a point is farther than this from the chord, ~3x range noise (see noise_from_scan) [m]");
	writeOption(c, s, "merge_residual", mergeResidual, "merge adjacent pieces if their union's RMS residual is below this, ~1.5x range noise (see noise_from_scan) [m]");
	writeOption(c, s, "merge_angle_deg", mergeAngleDeg, "... and their directions differ by less than this (or not significantly) [deg]");
	writeOption(c, s, "merge_gap", mergeGap, "pieces of two clusters merge only across a gap below this (or what spacing and noise explain) [m]");
	writeOption(c, s, "min_points", minPoints, "segments have at least this many points; smaller pieces only join neighbouring lines [points]");
	writeOption(c, s, "min_length", minLength, "drop segments shorter than this [m]");
}

ScanLineExtractor::ScanLineExtractor() : m_options() {}

ScanLineExtractor::ScanLineExtractor(const TOptions& options)
	: m_options(options)
{
}

std::vector<LineSegment> ScanLineExtractor::extract(
	const mrpt::obs::CObservation2DRangeScan& scan) const
{
	const double stated = scan.stdError;
	if (m_options.noiseFromScan && std::isfinite(stated) && stated > 0)
		return ScanLineExtractor(m_options.withRangeNoise(stated)).extract(scanPoints(scan));
	return extract(scanPoints(scan));
}

std::vector<ScanLineExtractor::Cluster> ScanLineExtractor::clusters(
	const ScanPoints& points) const
{
	// The sphere-of-influence graph, searched only `influenceWindow` points
	// either side in scan order. A scan is one sweep of a single origin, so a
	// point's neighbours on its own surface are its neighbours in bearing:
	// a point many rays away can only be nearer than those when the scan
	// folds back onto the same place, i.e. around an occlusion edge, and
	// there the rays in between hit something nearer. And clusters must be
	// runs of consecutive points anyway (each becomes a piece of profile
	// between two bearings), so an edge can only matter when it spans the
	// boundary between two consecutive points: a few points of look-ahead
	// bridge a lone outlier, more would bridge real gaps. So O(n W^2), not
	// O(n^2) or a k-d tree, with the same clusters for all practical scans.
	const auto& p = points.xy;
	const size_t n = p.size();
	const size_t w = static_cast<size_t>(m_options.influenceWindow);
	std::vector<Cluster> out;
	if (n == 0) return out;

	std::vector<double> radius(n, std::numeric_limits<double>::infinity());
	for (size_t i = 0; i < n; i++)
		for (size_t j = i + 1; j < n && j <= i + w; j++)
		{
			const double d = (p[i] - p[j]).norm();
			radius[i] = std::min(radius[i], d);
			radius[j] = std::min(radius[j], d);
		}
	for (auto& r : radius) r = std::max(r, m_options.minInfluenceRadius);
	auto connected = [&](size_t i, size_t j) {
		const double d = (p[i] - p[j]).norm();
		return d <= radius[i] + radius[j] && d <= m_options.maxGap;
	};
	// Is there an edge (i, j) with i <= k < j, i.e. across the boundary
	// between points k and k + 1?
	auto bridged = [&](size_t k) {
		for (size_t i = (k + 1 > w ? k + 1 - w : 0); i <= k; i++)
			for (size_t j = k + 1; j < n && j <= i + w; j++)
				if (connected(i, j)) return true;
		return false;
	};

	size_t first = 0;
	for (size_t k = 0; k < n; k++)
	{
		if (k + 1 < n && bridged(k)) continue;
		out.push_back({first, k});
		first = k + 1;
	}
	return out;
}

std::vector<LineSegment> ScanLineExtractor::extract(const ScanPoints& pts) const
{
	using detail::Piece;
	detail::PieceBuilder builder(pts, m_options);
	std::vector<Piece> pieces;
	const auto found = clusters(pts);
	for (size_t c = 0; c < found.size(); c++)
		builder.splitIepf(found[c].first, found[c].last, c, pieces);
	builder.setNoise(builder.noiseLevel(pieces));
	builder.trimEnds(pieces, true);
	// Lines first; then the small pieces' points join them where they fit,
	// what is left may make lines of its own, and the rest is dropped.
	builder.mergePieces(pieces, false);
	builder.absorbSmallPieces(pieces, true);
	builder.mergePieces(pieces, true);
	builder.absorbSmallPieces(pieces, false);
	// Small pieces gone, lines that they kept apart may now be neighbours.
	builder.mergePieces(pieces, false);
	builder.refineBoundaries(pieces);
	// A boundary may have left a piece too small to stand, or a stray.
	builder.absorbSmallPieces(pieces, false);
	builder.mergePieces(pieces, false);
	builder.setNoise(builder.noiseLevel(pieces));
	builder.trimEnds(pieces, false);

	std::vector<LineSegment> out;
	size_t lastCluster = std::numeric_limits<size_t>::max(), clusterNumber = 0;
	for (const Piece& piece : pieces)
	{
		if (piece.size() < static_cast<size_t>(m_options.minPoints)) continue;
		const LineFit fit = fitLine(piece.moments);
		LineSegment s;
		// The fit is relative to the sensor (at 0): orient the normal so
		// that the sensor is on its positive side, then move to the robot
		// frame.
		s.normal = fit.offset > 0 ? Eigen::Vector2d(-fit.normal) : fit.normal;
		s.offset = -std::abs(fit.offset) + s.normal.dot(pts.origin);
		auto project = [&](const Eigen::Vector2d& p) {
			return Eigen::Vector2d(p - s.signedDistance(p) * s.normal);
		};
		s.start = project(pts.xy[piece.first]);
		s.end = project(pts.xy[piece.last]);
		if (s.length() < m_options.minLength) continue;
		s.firstIndex = pts.ray[piece.first];
		s.lastIndex = pts.ray[piece.last];
		s.pointCount = piece.size();
		s.rmsResidual = fit.rmsResidual;
		if (piece.cluster != lastCluster && !out.empty()) clusterNumber++;
		lastCluster = piece.cluster;
		s.cluster = clusterNumber;
		out.push_back(s);
	}
	return out;
}

}  // namespace lvf::lines
