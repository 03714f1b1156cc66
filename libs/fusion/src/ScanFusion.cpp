#include <lvfusion/common/IniSection.h>
#include <lvfusion/common/LaserRange.h>
#include <lvfusion/common/ObservationLabels.h>
#include <lvfusion/fusion/NarrowGapBridging.h>
#include <lvfusion/fusion/ScanFusion.h>
#include <mrpt/core/bits_math.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lvf::fusion
{
using lvf::common::writeOption;

void ScanFusion::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	minPoints = ini.integer("min_points", minPoints, 1, 10000);
	clusterTolerance = ini.real("cluster_tolerance", clusterTolerance, 0, 10);
	centreSlack = ini.real("centre_slack", centreSlack, -0.5, 0.5);
	centralShare = ini.real("central_share", centralShare, 0, 0.5);
	rangeSupport = ini.real("range_support", rangeSupport, 0, 10);
	standingMedianShift = ini.real("standing_median_shift", standingMedianShift, 0, 10);
	bridgeWidth = ini.real("bridge_width", bridgeWidth, 0, 10);
	neighbourBins = ini.integer("neighbour_bins", neighbourBins, 0, 10);
	binWidthDeg = ini.real("bin_width_deg", binWidthDeg, 0, 360);
	ini.rejectUnknownKeys();
}

void ScanFusion::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "min_points", minPoints, "visual points a bearing needs before vision may shorten it");
	writeOption(c, s, "cluster_tolerance", clusterTolerance, "those points must lie within this span of range [m]");
	writeOption(c, s, "centre_slack", centreSlack, "and straddle the bin's bearing, give or take this fraction of a bin (negative: reach past it on both sides by that much)");
	writeOption(c, s, "central_share", centralShare, "the bearing's range is the nearest of its cluster's min_points points nearest the bin's bearing, and of any others nearer it than this fraction of a bin; 0: off [0..0.5]");
	writeOption(c, s, "range_support", rangeSupport, "that nearest point needs another point of the cluster within this much range of it (else the next one; all isolated: their median); 0: off [m]");
	writeOption(c, s, "standing_median_shift", standingMedianShift, "on a standing surface (the cluster's points span more height than range) the range moves from that nearest point toward the median of the points it was chosen from, by at most this much disparity; a lying one (a table top) keeps its nearest point, its front edge; 0: the nearest everywhere [px]");
	writeOption(c, s, "neighbour_bins", neighbourBins, "a bin with fewer than min_points points of its own may count those of the bins up to this many either side, some on each side (its own nearest point with such a cluster behind it sets the range); 0: off");
	writeOption(c, s, "bin_width_deg", binWidthDeg, "a bearing's bin of visual points, centred on it, at least the laser's ray spacing: with a finer laser neighbouring bins overlap [deg]");
	writeOption(c, s, "bridge_width", bridgeWidth, "close gaps in an edge at most this wide between two bearings whose ranges agree within cluster_tolerance, one of them set by vision: bearings between that are farther than both, and not placed by vision within cluster_tolerance of them, take the line between them; 0: off [m]");
}

namespace
{
/** The median range of [first, last) (reorders it). */
template <typename It>
float medianRange(It first, It last)
{
	const It median = first + (last - first) / 2;
	std::nth_element(first, median, last, [](const auto& a, const auto& b) { return a.range < b.range; });
	return median->range;
}

/** Whether a cluster's points span more height than range: a standing
 * surface, seen at one range from bottom to top, rather than a lying one
 * seen over a span of range at one height. */
template <typename It>
bool standsUp(It first, It last)
{
	const auto [lowest, highest] =
		std::minmax_element(first, last, [](const auto& a, const auto& b) { return a.height < b.height; });
	const auto [nearest, farthest] =
		std::minmax_element(first, last, [](const auto& a, const auto& b) { return a.range < b.range; });
	return highest->height - lowest->height >= farthest->range - nearest->range;
}
}  // namespace

float ScanFusion::rangeAlongTheRay(std::vector<Hit>::iterator first, std::vector<Hit>::iterator last) const
{
	// On a slanted face the points differ in range with bearing, so look at
	// those nearest the bin's bearing: the min_points nearest, and any
	// others nearer it than central_share of a bin.
	std::sort(first, last, [](const Hit& a, const Hit& b) { return std::abs(a.offset) < std::abs(b.offset); });
	auto chosenEnd = first + std::min<long>(m_options.minPoints, last - first);
	while (chosenEnd != last && std::abs(chosenEnd->offset) < m_options.centralShare) chosenEnd++;
	// Of them the nearest, since a horizontal surface (a table top seen from
	// above) starts at its nearest point; but not a point no other point of
	// the cluster lies near: that is the tail of the matching noise.
	auto supported = [&](const Hit& h) {
		return std::any_of(first, last, [&](const Hit& o) {
			return &o != &h && std::abs(o.range - h.range) <= m_options.rangeSupport;
		});
	};
	float nearest = std::numeric_limits<float>::infinity(), nearestDisparity = 0;
	for (auto it = first; it != chosenEnd; ++it)
		if ((m_options.rangeSupport <= 0 || supported(*it)) && it->range < nearest)
			nearest = it->range, nearestDisparity = it->disparity;
	// All of them isolated (points spread over the tolerance): their median.
	if (!std::isfinite(nearest)) return medianRange(first, chosenEnd);
	// A standing surface lies at one range: toward the chosen points'
	// median, away from the noise's near tail, but no farther than the
	// nearest point's range at standing_median_shift less disparity (along
	// its ray the range goes as 1 / disparity, nearly: it is measured from
	// the laser, not the cameras). A remembered point has no disparity
	// (NaN): it stays. The spans standsUp compares do not depend on the
	// order the choice above left the cluster in.
	const auto shift = static_cast<float>(m_options.standingMedianShift);
	if (!(shift > 0 && nearestDisparity > shift) || !standsUp(first, last)) return nearest;
	const float bound = nearest * nearestDisparity / (nearestDisparity - shift);
	return std::clamp(medianRange(first, chosenEnd), nearest, bound);
}

float ScanFusion::rangeWithNeighbours(const std::vector<Hit>& own, const std::vector<Hit>& around) const
{
	std::vector<float> starts;
	for (const Hit& h : own) starts.push_back(h.range);
	std::sort(starts.begin(), starts.end());
	for (const float start : starts)
	{
		// The points of this bin and its neighbours within the tolerance
		// behind this one. The surface must go on into a bin on each side:
		// one-sided, its points beside the ray would decide (a wrong match
		// that does not reach the next bins, or an obstacle's end).
		size_t count = 0, atStart = 0;
		bool below = false, above = false, supported = m_options.rangeSupport <= 0;
		for (const Hit& h : around)
		{
			if (h.range < start || h.range - start > m_options.clusterTolerance) continue;
			count++;
			below |= h.offset < -0.5f, above |= h.offset >= 0.5f;
			// Supported by another point within range_support behind it; the
			// first point at the start's own range is the start itself.
			if (h.range - start <= m_options.rangeSupport) supported |= h.range != start || ++atStart > 1;
		}
		if (count >= size_t(m_options.minPoints) && supported && below && above) return start;
	}
	return std::numeric_limits<float>::infinity();
}

void ScanFusion::hitsAround(const std::vector<std::vector<PlanePoint>>& byRay, size_t i, double binRays,
	double halfWidths, std::vector<Hit>& hits) const
{
	const double lo = double(i) - halfWidths * binRays, hi = double(i) + halfWidths * binRays;
	const long last = long(byRay.size()) - 1;
	hits.clear();
	for (long j = std::max(0L, std::lround(lo)); j <= std::min(last, std::lround(hi)); j++)
		for (const PlanePoint& p : byRay[size_t(j)])
			if (p.index >= lo && p.index < hi)
				hits.push_back({p.range, static_cast<float>((p.index - double(i)) / binRays), p.atImageEdge, p.height, p.disparity});
}

std::vector<std::vector<ScanFusion::PlanePoint>> ScanFusion::pointsUnderRays(
	const mrpt::obs::CObservation2DRangeScan& laser, const std::vector<lvf::depth::VisualPoint>& points,
	std::optional<SearchedColumns> searched)
{
	// Remembered points (VisualPointMemory) have no pixel: u is NaN.
	auto atImageEdge = [&](float u) {
		return searched && std::isfinite(u) && (u - searched->first < searched->step || searched->last - u < searched->step);
	};
	const size_t n = laser.getScanSize();
	// Into the laser's frame: R^T (p - t), its rows taken once (MRPT's
	// per-point inverseComposePoint costs about as much as the rest here).
	const Eigen::Matrix3d laserToRobot = laser.sensorPose.getRotationMatrix().asEigen();
	const Eigen::Vector3d laserOrigin(laser.sensorPose.x(), laser.sensorPose.y(), laser.sensorPose.z());
	const Eigen::RowVector3d xAxis = laserToRobot.col(0).transpose(), yAxis = laserToRobot.col(1).transpose();
	std::vector<std::vector<PlanePoint>> onPlane(n);
	for (const auto& p : points)
	{
		// Projected onto the laser's (horizontal) plane.
		const Eigen::Vector3d d = p.robot - laserOrigin;
		const double x = xAxis * d, y = yAxis * d;
		const double index = rayIndexOf(laser, std::atan2(y, x));
		const long ray = std::lround(index);
		if (ray < 0 || ray >= long(n)) continue;
		onPlane[size_t(ray)].push_back(
			{index, static_cast<float>(std::hypot(x, y)), atImageEdge(p.u), static_cast<float>(p.robot.z()), p.disparity});
	}
	return onPlane;
}

float ScanFusion::rangeOfOwnCluster(std::vector<Hit>& hits) const
{
	const size_t need = static_cast<size_t>(m_options.minPoints);
	const float slack = static_cast<float>(m_options.centreSlack);
	std::sort(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.range < b.range; });
	// The nearest run of at least `need` points spanning at most the
	// tolerance in range...
	for (size_t k = 0; k + need <= hits.size(); k++)
	{
		if (hits[k + need - 1].range - hits[k].range > m_options.clusterTolerance) continue;
		size_t end = k + need;
		while (end < hits.size() && hits[end].range - hits[k].range <= m_options.clusterTolerance) end++;
		// ...that also covers the bin's own bearing: at an obstacle's edge
		// a bin may hold points from beside its ray, which the ray misses.
		float lo = 1, hi = -1;
		bool edge = false;
		for (size_t j = k; j < end; j++)
			lo = std::min(lo, hits[j].offset), hi = std::max(hi, hits[j].offset), edge |= hits[j].atImageEdge;
		if (!edge && (lo > slack || hi < -slack)) continue;
		return rangeAlongTheRay(hits.begin() + long(k), hits.begin() + long(end));
	}
	return std::numeric_limits<float>::infinity();
}

std::vector<float> ScanFusion::visualRanges(
	const mrpt::obs::CObservation2DRangeScan& laser,
	const std::vector<lvf::depth::VisualPoint>& points, std::optional<SearchedColumns> searched,
	std::vector<bool>* bridged) const
{
	const size_t n = laser.getScanSize();
	const double rayStep = lvf::rayStep(laser.aperture, n);
	// A bin's width in rays: at least one.
	const double binRays = std::max(1.0, mrpt::DEG2RAD(m_options.binWidthDeg) / rayStep);
	// Each point under the ray it rounds to (a bin gathers from the rays it spans).
	const std::vector<std::vector<PlanePoint>> onPlane = pointsUnderRays(laser, points, searched);

	std::vector<float> out(n, std::numeric_limits<float>::infinity());
	std::vector<Hit> hits, around;	// reused from ray to ray
	for (size_t i = 0; i < n; i++)
	{
		hitsAround(onPlane, i, binRays, 0.5, hits);
		if (hits.empty()) continue;
		if (hits.size() >= static_cast<size_t>(m_options.minPoints))
			out[i] = rangeOfOwnCluster(hits);
		else if (m_options.neighbourBins > 0)
		{
			// Too few of its own: with its neighbours' (neighbour_bins).
			hitsAround(onPlane, i, binRays, m_options.neighbourBins + 0.5, around);
			out[i] = rangeWithNeighbours(hits, around);
		}
	}
	if (m_options.bridgeWidth > 0)
	{
		std::vector<float> laserRanges(n);
		for (size_t i = 0; i < n; i++) laserRanges[i] = laserRangeOrMax(laser, i);
		const auto closed = bridgeNarrowGaps(out, laserRanges, rayStep, m_options.bridgeWidth, m_options.clusterTolerance);
		if (bridged) *bridged = closed;
	}
	else if (bridged)
		bridged->assign(n, false);
	return out;
}

mrpt::obs::CObservation2DRangeScan::Ptr ScanFusion::fuse(
	const mrpt::obs::CObservation2DRangeScan& laser, const std::vector<float>& visual)
{
	auto fused = std::make_shared<mrpt::obs::CObservation2DRangeScan>(laser);
	fused->sensorLabel = lvf::common::kFusedScanLabel;
	for (size_t i = 0; i < fused->getScanSize(); i++)
	{
		if (i < visual.size() && visual[i] < laserRangeOrMax(laser, i))
		{
			fused->setScanRange(i, visual[i]);
			fused->setScanRangeValidity(i, true);
		}
	}
	return fused;
}

}  // namespace lvf::fusion
