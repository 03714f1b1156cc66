// FocusedEpipolarSearch: which pixels are searched, over which disparities
// (the criteria and the band), in which order (the grid's rows in bands on
// OpenCV's threads; coarse rows first with nearest first), and what becomes
// of a match (sub-pixel peak, triangulation, the band). The match of one
// pixel: FullResolutionMatch.cpp and CoarseToFineMatch.cpp.

#include <lvfusion/common/RowBands.h>
#include <lvfusion/depth/DisparityInterval.h>
#include <lvfusion/depth/EpipolarScores.h>
#include <lvfusion/depth/FocusedEpipolarSearch.h>
#include <lvfusion/depth/NearestPerBearing.h>
#include "SubpixelRefinement.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace lvf::depth
{
using lvf::evaluation::PixelState;

namespace
{
constexpr double kInfinity = std::numeric_limits<double>::infinity();
/** A model point this close to the floor's height is the model's floor [m]
 * (the model's surfaces are exact planes: only rounding separates them). */
constexpr double kOnTheFloor = 1e-3;

/** Whether the model check leaves a pixel in this state to the search. */
bool leftToTheSearch(PixelState state) { return state == PixelState::Inconsistent || state == PixelState::Unmodelled; }

/** Per image row, whether the search's grid (rows and columns half,
 * half + stride, ...) has a pixel there that it will match: left to it and
 * textured. The seeded rooms leave a third of the grid's rows without one
 * (rooms 301-319: 0.31 on average, 0.01-0.54 a frame), and the levels'
 * statistics are needed only on the others. */
std::vector<uint8_t> gridRowsToSearch(const lvf::evaluation::ModelEvaluation& evaluation, int half, int stride, double textureGate)
{
	const int H = evaluation.state.rows, W = evaluation.state.cols;
	std::vector<uint8_t> wanted(static_cast<size_t>(H), 0);
	for (int v = half; v < H - half; v += stride)
	{
		const int gridRow = evaluation.grid.index(v);
		for (int u = half; u < W - half && !wanted[static_cast<size_t>(v)]; u += stride)
			wanted[static_cast<size_t>(v)] = leftToTheSearch(static_cast<PixelState>(evaluation.state(v, u))) &&
				evaluation.gridLeftStd(gridRow, evaluation.grid.index(u)) >= textureGate;
	}
	return wanted;
}

/** Two passes' points, each in row order, as one list in row order. */
std::vector<VisualPoint> mergedByRow(const std::vector<VisualPoint>& a, const std::vector<VisualPoint>& b)
{
	std::vector<VisualPoint> out;
	out.reserve(a.size() + b.size());
	std::merge(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out),
		[](const VisualPoint& p, const VisualPoint& q) { return p.v < q.v; });
	return out;
}
}  // namespace

DisparitySet FocusedEpipolarSearch::allowedDisparities(
	int u, double modelDisparity, const Eigen::Vector3d& ray, const Eigen::Vector3d& camera,
	int half, const lvf::evaluation::RectifiedGeometry& g, const HeightBand& band, bool floorModel) const
{
	const double fB = g.fB();
	// Disparities whose right window lies inside the image.
	DisparitySet set({std::max(0.5, u + g.cxOffset - (g.size.width - 1 - half)), u + g.cxOffset - half});
	if (m_options.criterionC) set.intersect({fB / m_options.zMax, fB / m_options.zMin});
	if (modelDisparity > 0)
	{
		const double zModel = fB / modelDisparity;
		if (m_options.criterionB) set.intersect({modelDisparity, kInfinity});
		// Criterion a says how close to the model is too close by depth along
		// the ray. On the floor that measure is off: a ray meets the floor at
		// a grazing angle, so d_allow of depth is only a few centimetres of
		// height there (Z h / (H - h): 0.07 m of depth for 5 cm at 1.5 m from
		// a camera 1.1 m up), and it keeps the search off the lowest part of
		// obstacles standing on the floor (Middlebury's Recycle: the bins'
		// bases). floor_disparity_margin narrows it there to what matching
		// cannot tell from the floor (within 2 px the floor's own column lies
		// on the match's peak, where the model check cannot see it; lifted
		// altogether, criterion a let points 5-9 cm up through on the
		// simulator's bare, smooth floor), and the band's lower edge below
		// decides what is an obstacle (floorDisparityMargin, 2 px by default).
		double nearer = zModel > m_options.dAllow ? fB / (zModel - m_options.dAllow) : kInfinity;
		if (floorModel && m_options.boundByBand && m_options.floorDisparityMargin > 0)
			nearer = std::min(nearer, modelDisparity + m_options.floorDisparityMargin);
		if (m_options.criterionA) set.remove(fB / (zModel + m_options.dAllow), nearer);
	}
	if (m_options.boundByBand)
	{
		// Height along the ray: camera.z + Z ray.z, for depth Z.
		if (std::abs(ray.z()) < 1e-12)
		{
			if (!band.contains(camera.z())) set.intersect({1, 0});
		}
		else
		{
			const double z1 = (band.low - camera.z()) / ray.z(), z2 = (band.high - camera.z()) / ray.z();
			const double zNear = std::min(z1, z2), zFar = std::max(z1, z2);
			if (zFar <= 0) set.intersect({1, 0});
			else set.intersect({fB / zFar, zNear > 0 ? fB / zNear : kInfinity});
		}
	}
	return set;
}


/** What every grid row of one frame's search reads. */
struct FocusedEpipolarSearch::Frame
{
	const lvf::evaluation::ModelEvaluation& evaluation;
	const lvf::evaluation::RectifiedGeometry& g;
	const HeightBand& band;
	double floorHeight;
	int half;
	double textureGate;
	const SubpixelRefinement& refinement;
};

/** Which grid rows one pass searches, and what bounds it. */
struct FocusedEpipolarSearch::Pass
{
	int firstRow, rowStep;
	/** A later pass: what the passes before it found per bearing, which a
	 * pixel is searched only in front of (nullptr: the first pass). */
	const NearestPerBearing* nearer = nullptr;
};

/** What the search found on some of its grid rows. */
struct FocusedEpipolarSearch::RowsFound
{
	std::vector<VisualPoint> points;
	DepthSearchStats stats;
};

void DepthSearchStats::count(SearchOutcome o)
{
	switch (o)
	{
		case SearchOutcome::NotSearched: return;
		case SearchOutcome::Untextured: skippedUntextured++; return;
		case SearchOutcome::EmptyRange: skippedEmptyRange++; return;
		case SearchOutcome::BehindNearer: skippedBehindNearer++; return;
		default: break;
	}
	// The rest were matched.
	searchedPixels++;
	switch (o)
	{
		case SearchOutcome::Weak: rejectedWeak++; break;
		case SearchOutcome::NotPeak: rejectedNotPeak++; break;
		case SearchOutcome::Ambiguous: rejectedAmbiguous++; break;
		case SearchOutcome::LeftRight: rejectedLeftRight++; break;
		case SearchOutcome::OutOfBand: rejectedOutOfBand++; break;
		case SearchOutcome::CoreMismatch: rejectedCore++; break;
		case SearchOutcome::Accepted: accepted++; break;
		default: break;
	}
}

void FocusedEpipolarSearch::searchRows(
	int firstRow, int endRow, const Pass& pass, MatchingLevel& full, MatchingLevel* coarse, const Frame& frame,
	RowsFound& found, cv::Mat1b& outcome) const
{
	const int W = full.left.cols;
	for (int v = firstRow; v < endRow; v += pass.rowStep)
		for (int u = frame.half; u < W - frame.half; u += m_options.pixelStride)
		{
			if (!leftToTheSearch(static_cast<PixelState>(frame.evaluation.state(v, u)))) continue;
			const SearchOutcome o = searchPixel(u, v, pass, full, coarse, frame, found.points);
			outcome(v, u) = static_cast<uint8_t>(o);
			found.stats.count(o);
		}
}

SearchOutcome FocusedEpipolarSearch::searchPixel(
	int u, int v, const Pass& pass, MatchingLevel& full, MatchingLevel* coarse, const Frame& frame,
	std::vector<VisualPoint>& points) const
{
	const auto& evaluation = frame.evaluation;
	const auto& g = frame.g;
	// The pixel's place on the evaluation's grid, once (a division each way).
	const int gridRow = evaluation.grid.index(v), gridColumn = evaluation.grid.index(u);
	const float leftStd = evaluation.gridLeftStd(gridRow, gridColumn);
	if (leftStd < frame.textureGate) return SearchOutcome::Untextured;
	const Eigen::Vector3d C = g.cameraCentre();
	const double fB = g.fB();
	const double dModel = evaluation.modelDisparity(v, u);
	const Eigen::Vector3d ray = g.robotRay(u, v);
	const bool floorModel = m_options.floorDisparityMargin > 0 && dModel > 0 &&
		std::abs(C.z() + fB / dModel * ray.z() - frame.floorHeight) < kOnTheFloor;
	DisparitySet set = allowedDisparities(u, dModel, ray, C, frame.half, g, frame.band, floorModel);
	if (set.empty() || set.integerCount() == 0) return SearchOutcome::EmptyRange;
	if (pass.nearer)
	{
		// Depth Z puts the point Z |ray_xy| from the camera, horizontally.
		const double bound = pass.nearer->along(ray);
		if (std::isfinite(bound)) set.intersect({fB * std::hypot(ray.x(), ray.y()) / bound, kInfinity});
		if (set.empty() || set.integerCount() == 0) return SearchOutcome::BehindNearer;
	}
	const PixelQuery query{u, v, evaluation.gridLeftMean(gridRow, gridColumn), leftStd, dModel, set, g};
	const Match m = coarse ? matchCoarseToFine(full, *coarse, query) : matchAtFullResolution(full, query);
	if (m.outcome != SearchOutcome::Accepted) return m.outcome;
	// Last, on what passed everything else: the fewest pixels.
	if (m_options.shiftedWindows && dModel > 0 && modelExplainsASide(full, query, m.x))
		return SearchOutcome::CoreMismatch;
	return triangulate(query, m, ray, full, frame, points);
}

SearchOutcome FocusedEpipolarSearch::triangulate(const PixelQuery& q, const Match& m, const Eigen::Vector3d& ray,
	MatchingLevel& full, const Frame& frame, std::vector<VisualPoint>& points) const
{
	const auto& g = frame.g;
	const Eigen::Vector3d C = g.cameraCentre();
	const double fB = g.fB();
	// Parabola through the peak and its neighbours, then the images.
	const float curvature = m.before - 2 * m.score + m.after;
	const float shift = curvature < 0 ? 0.5f * (m.before - m.after) / curvature : 0.f;
	const double column =
		frame.refinement.refine(full.left, full.right, q.u, q.v, m.x + shift, m_options.subpixelIterations);
	const double disparity = q.u + g.cxOffset - column;
	// Refined to no disparity, the point would lie at infinity (or behind
	// the cameras): no depth in the band either.
	const bool finite = disparity > 0;
	const Eigen::Vector3d p = finite ? Eigen::Vector3d(C + (fB / disparity) * ray) : C;
	if (!finite || !frame.band.contains(p.z())) return SearchOutcome::OutOfBand;
	points.push_back({static_cast<float>(q.u), static_cast<float>(q.v), static_cast<float>(disparity), m.score, p});
	// The outermost grid columns' windows also cover the image's last
	// columns, where no window fits: their match is the depth there too
	// (rays at the image's edge would see nothing otherwise).
	const int W = full.left.cols, half = frame.half, stride = m_options.pixelStride;
	auto extendTo = [&](int ue) {
		const Eigen::Vector3d pe = C + (fB / disparity) * g.robotRay(ue, q.v);
		if (frame.band.contains(pe.z()))
			points.push_back({static_cast<float>(ue), static_cast<float>(q.v), static_cast<float>(disparity), m.score, pe});
	};
	if (q.u - stride < half)
		for (int ue = q.u - stride; ue >= std::max(0, q.u - half); ue -= stride) extendTo(ue);
	if (q.u + stride > W - 1 - half)
		for (int ue = q.u + stride; ue <= std::min(W - 1, q.u + half); ue += stride) extendTo(ue);
	return SearchOutcome::Accepted;
}

FocusedEpipolarSearch::RowsFound FocusedEpipolarSearch::searchPass(
	const Pass& pass, int endRow, MatchingLevel& full, MatchingLevel* coarse, const Frame& frame,
	cv::Mat1b& outcome) const
{
	// Each pixel is matched on its own: bands of the pass's rows on
	// OpenCV's threads, each band with views of the levels that score for it
	// alone; the bands' points joined in row order are the single thread's.
	// Many narrow bands: the rows an obstacle fills cost several times the
	// others (box room, 2 threads against 1: the search stage 1.59x as fast
	// with 4 bands a thread, 1.66x with 16).
	const lvf::common::RowBands bands(pass.firstRow, endRow, pass.rowStep, 16);
	std::vector<RowsFound> found(static_cast<size_t>(bands.count()));
	bands.forEach([&](int b, int firstRow, int bandEnd) {
		std::unique_ptr<MatchingLevel> fullView, coarseView;
		if (bands.count() > 1)
		{
			fullView = full.forAnotherThread();
			if (coarse) coarseView = coarse->forAnotherThread();
		}
		MatchingLevel& f = fullView ? *fullView : full;
		MatchingLevel* c = coarseView ? coarseView.get() : coarse;
		// (One band scores with the levels themselves, which count on from
		// an earlier pass.)
		auto tested = [&] { return f.forward.evaluations() + (c ? c->forward.evaluations() : 0); };
		const size_t before = tested();
		RowsFound& rows = found[size_t(b)];
		searchRows(firstRow, bandEnd, pass, f, c, frame, rows, outcome);
		rows.stats.disparitiesTested = tested() - before;
	});
	RowsFound all;
	for (const RowsFound& rows : found)
	{
		all.points.insert(all.points.end(), rows.points.begin(), rows.points.end());
		all.stats += rows.stats;
	}
	return all;
}

FocusedEpipolarSearch::Result FocusedEpipolarSearch::search(
	const cv::Mat1b& left, const cv::Mat1b& right,
	const lvf::evaluation::ModelEvaluation& evaluation, int windowSize,
	const lvf::evaluation::RectifiedGeometry& g, const HeightBand& band, double floorHeight) const
{
	Result out;
	const int half = windowSize / 2;
	const int W = left.cols, H = left.rows;
	const double textureGate = m_options.textureGate(evaluation.noiseStd);
	// Pixels are matched only on the grid's rows that hold one to search
	// (and, coarse to fine, on the coarse level's rows under them):
	// statistics there alone.
	MatchingLevel full(left, right, half,
		RowGrid{half, m_options.pixelStride, gridRowsToSearch(evaluation, half, m_options.pixelStride, textureGate)});
	std::unique_ptr<MatchingLevel> coarse;
	if (m_options.coarseToFine) coarse = std::make_unique<MatchingLevel>(full, std::max(1, half / 2));
	// Every coarse-to-fine match reads the coarse left window's statistics.
	if (coarse) coarse->prepareLeftStatistics();
	out.outcome = cv::Mat1b::zeros(H, W);
	const SubpixelRefinement refinement(half, m_options.subpixelSigma);
	const Frame frame{evaluation, g, band, floorHeight, half, textureGate, refinement};

	// Coarse rows first (nearest_first_levels = L): every 2^L-th grid row,
	// then the rows halfway between, and so on down to every grid row; a
	// pass after the first searches a pixel only in front of what the
	// passes before it found on its bearing. L = 0: every grid row at once.
	const int stride = m_options.pixelStride, levels = m_options.nearestFirstLevels;
	NearestPerBearing nearest(g.cameraCentre(), static_cast<size_t>(m_options.nearestFirstPoints));
	for (int level = levels; level >= 0; level--)
	{
		const int step = stride << level;
		const Pass pass = level == levels ? Pass{half, step} : Pass{half + step, 2 * step, &nearest};
		RowsFound found = searchPass(pass, H - half, full, coarse.get(), frame, out.outcome);
		if (level > 0)
		{
			// Each pass's points join the bounds of the passes after it.
			for (const VisualPoint& p : found.points) nearest.add(p.robot);
			nearest.finish();
		}
		out.points = mergedByRow(out.points, found.points);
		out.stats += found.stats;
	}

	// The grid's first and last columns, and as far beyond them as
	// whole strides stay within half a window: the columns searchRows'
	// edge points (extendTo) reach, so that what reads these bounds (the
	// fusion's image-edge test, the memory's view) agrees with the points.
	const int lastGridColumn = half + ((W - 1 - 2 * half) / stride) * stride;
	const int reach = (half / stride) * stride;
	out.firstColumn = static_cast<float>(half - reach);
	out.lastColumn = static_cast<float>(lastGridColumn + reach);
	return out;
}

}  // namespace lvf::depth
