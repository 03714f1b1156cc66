#include <lvfusion/common/IniSection.h>
#include <lvfusion/depth/HorizontalSurfaceGrowth.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <utility>

namespace lvf::depth
{
using lvf::common::writeOption;

void HorizontalSurfaceGrowth::TOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	lvf::common::IniSection ini(source, section);
	enabled = ini.flag("enabled", enabled);
	sideways = ini.flag("sideways", sideways);
	acceptNcc = ini.real("accept_ncc", acceptNcc, -1, 1);
	windowHalfWidth = ini.integer("window_half_width", windowHalfWidth, 1, 50);
	windowHalfHeight = ini.integer("window_half_height", windowHalfHeight, 0, 50);
	modelMargin = ini.real("model_margin", modelMargin, 0, 2);
	heightSearch = ini.real("height_search", heightSearch, 0, 1);
	heightTolerance = ini.real("height_tolerance", heightTolerance, 0, 10);
	minRangeStep = ini.real("min_range_step", minRangeStep, 0, 10);
	witnessStrides = ini.integer("witness_strides", witnessStrides, 1, 1000);
	maxSlope = ini.real("max_slope", maxSlope, 0, 1000);
	ini.rejectUnknownKeys();
}

void HorizontalSurfaceGrowth::TOptions::saveToConfigFile(
	mrpt::config::CConfigFileBase& c, const std::string& s) const
{
	writeOption(c, s, "enabled", enabled, "follow horizontal surfaces the search found towards the camera, row by row (true/false)");
	writeOption(c, s, "sideways", sideways, "also follow each surface sideways along its start row, a grid column at a time, and each such column to the surface's edge (true/false)");
	writeOption(c, s, "accept_ncc", acceptNcc, "each row's window, sheared as the plane shears it, must score this NCC [-1..1]");
	writeOption(c, s, "window_half_width", windowHalfWidth, "that window's half width [px]");
	writeOption(c, s, "window_half_height", windowHalfHeight, "its half height [px]; the last this many rows of a walk are dropped (the window straddles the edge there)");
	writeOption(c, s, "model_margin", modelMargin, "the plane must beat the scene model's own disparity by this NCC");
	writeOption(c, s, "height_search", heightSearch, "the plane's height is fitted to the images within this of the start point's (in 5 mm steps; 0: the point's own) [m]");
	writeOption(c, s, "height_tolerance", heightTolerance, "two search points are on one horizontal surface if their heights differ by at most this [m]");
	writeOption(c, s, "min_range_step", minRangeStep, "and the one nearer the image's edge is at least this much nearer the robot [m]");
	writeOption(c, s, "witness_strides", witnessStrides, "and they are at most this many pixel_stride steps apart on their column");
	writeOption(c, s, "max_slope", maxSlope, "and their heights differ by at most this fraction of their ranges' difference (a leg's points, noisy in range, are no surface) [m/m]");
}

namespace
{
/** A left window matched against the right image under the hypothesis that
 * it shows the horizontal plane z = h (robot frame): each window row at the
 * disparity the plane gives that row's ray, the right row sampled between
 * pixels by linear interpolation. */
class PlaneWindow
{
   public:
	PlaneWindow(
		const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& g, double h,
		int halfWidth, int halfHeight)
		: m_left(left),
		  m_right(right),
		  m_g(g),
		  m_camera(g.cameraCentre()),
		  m_h(h),
		  m_halfWidth(halfWidth),
		  m_halfHeight(halfHeight)
	{
	}

	/** The plane's disparity at pixel (u, v), if its ray meets the plane in
	 * front of the camera. */
	std::optional<double> disparity(int u, int v) const
	{
		const double rz = m_g.robotRay(u, v).z();
		if (std::abs(rz) < 1e-9) return std::nullopt;
		const double depth = (m_h - m_camera.z()) / rz;
		if (depth <= 0) return std::nullopt;
		return m_g.fB() / depth;
	}

	/** The robot-frame point of pixel (u, v) at disparity d. */
	Eigen::Vector3d point(int u, int v, double d) const { return m_camera + (m_g.fB() / d) * m_g.robotRay(u, v); }

	struct Score
	{
		double ncc;
		double leftStd;
	};
	/** NCC of the window centred on (u, v), every row `shift` px off the
	 * plane's disparity; none if a window row leaves either image or misses
	 * the plane, or a window is flat. */
	std::optional<Score> score(int u, int v, double shift) const
	{
		if (v - m_halfHeight < 0 || v + m_halfHeight >= m_left.rows || u - m_halfWidth < 0 ||
			u + m_halfWidth >= m_left.cols)
			return std::nullopt;
		double sl = 0, sr = 0, sll = 0, srr = 0, slr = 0;
		for (int dy = -m_halfHeight; dy <= m_halfHeight; dy++)
		{
			const auto d = disparity(u, v + dy);
			if (!d) return std::nullopt;
			const double x0 = u - m_halfWidth + m_g.cxOffset - (*d + shift);
			const int xi = static_cast<int>(std::floor(x0));
			if (xi < 0 || xi + 2 * m_halfWidth + 1 >= m_right.cols) return std::nullopt;
			const double a = x0 - xi;
			const uint8_t* l = m_left.ptr<uint8_t>(v + dy) + u - m_halfWidth;
			const uint8_t* r = m_right.ptr<uint8_t>(v + dy) + xi;
			for (int k = 0; k <= 2 * m_halfWidth; k++)
			{
				const double lv = l[k], rv = (1 - a) * r[k] + a * r[k + 1];
				sl += lv, sr += rv, sll += lv * lv, srr += rv * rv, slr += lv * rv;
			}
		}
		const double n = double((2 * m_halfWidth + 1) * (2 * m_halfHeight + 1));
		const double ml = sl / n, mr = sr / n;
		const double varL = sll / n - ml * ml, varR = srr / n - mr * mr;
		if (varL <= 1e-9 || varR <= 1e-9) return std::nullopt;
		return Score{(slr / n - ml * mr) / std::sqrt(varL * varR), std::sqrt(varL)};
	}

   private:
	const cv::Mat1b& m_left;
	const cv::Mat1b& m_right;
	const lvf::evaluation::RectifiedGeometry& m_g;
	Eigen::Vector3d m_camera;
	double m_h;
	int m_halfWidth, m_halfHeight;
};

/** Whether the window's NCC, over disparities shifted from the plane's,
 * peaks within a pixel of it: the best of shifts 0 and +-1 px beats both
 * +-2 px. A smooth texture's NCC peak spans a few pixels, so that a plane
 * right to a fraction of a pixel can score a little under its neighbour at
 * 1 px; requiring the plane itself to beat +-1 px stopped most walks on
 * room 5's table top at their first rows (measurements.md). */
bool peaksNearThePlane(const PlaneWindow& plane, int u, int v, double atPlane)
{
	double inner = atPlane, outer = -2;
	for (const double shift : {-1.0, 1.0})
		if (const auto s = plane.score(u, v, shift)) inner = std::max(inner, s->ncc);
	for (const double shift : {-2.0, 2.0})
		if (const auto s = plane.score(u, v, shift)) outer = std::max(outer, s->ncc);
	return inner > outer;
}

double groundRange(const VisualPoint& p) { return std::hypot(p.robot.x(), p.robot.y()); }
}  // namespace

bool HorizontalSurfaceGrowth::hasWitness(
	const VisualPoint& p, const std::vector<VisualPoint>& points, const std::vector<size_t>& column, int step,
	int stride) const
{
	const TOptions& o = m_options;
	for (size_t j : column)
	{
		const VisualPoint& q = points[j];
		// The cheap tests first: most of a column's points are too many
		// rows away, and the ranges' square roots cost more than the rest.
		const double rows = step * (p.v - q.v);
		if (rows <= 0 || rows > o.witnessStrides * stride) continue;
		const double rise = std::abs(q.robot.z() - p.robot.z());
		if (rise > o.heightTolerance) continue;
		const double run = groundRange(q) - groundRange(p);
		if (run >= o.minRangeStep && rise <= o.maxSlope * run) return true;
	}
	return false;
}

double HorizontalSurfaceGrowth::fittedHeight(
	const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& g, int u,
	const VisualPoint& start, int step, int stride) const
{
	const TOptions& o = m_options;
	// Two rows the search found on the surface: the start and one two grid
	// rows behind it (away from the walk).
	const int rows[] = {static_cast<int>(start.v), static_cast<int>(start.v) - 2 * step * stride};
	double best = -4, fitted = start.robot.z();
	const int steps = static_cast<int>(std::lround(o.heightSearch / kHeightSearchStep));
	for (int k = -steps; k <= steps; k++)
	{
		const double h = start.robot.z() + k * kHeightSearchStep;
		const PlaneWindow trial(left, right, g, h, o.windowHalfWidth, o.windowHalfHeight);
		double total = 0;
		for (int v : rows)
		{
			const auto s = trial.score(u, v, 0.0);
			total += s ? s->ncc : -2;
		}
		if (total > best) best = total, fitted = h;
	}
	return fitted;
}

namespace
{
/** A row of a walk where the plane holds. */
struct PlaneRow
{
	int v;
	double disparity, ncc;
};

/** One plane's walks: where it holds, and each column followed from the
 * start row to the surface's edge. */
class SurfaceWalk
{
   public:
	SurfaceWalk(
		const PlaneWindow& plane, const lvf::evaluation::ModelEvaluation& evaluation, const HeightBand& band,
		const HorizontalSurfaceGrowth::TOptions& options, double textureGate, int stride, int startRow, int step)
		: m_plane(plane),
		  m_evaluation(evaluation),
		  m_band(band),
		  m_o(options),
		  m_textureGate(textureGate),
		  m_stride(stride),
		  m_startRow(startRow),
		  m_step(step)
	{
	}

	int startRow() const { return m_startRow; }

	/** The plane's row at (u, v), if its sheared window scores
	 * `accept_ncc` on texture, peaks near the plane and beats the model. */
	std::optional<PlaneRow> holds(int u, int v) const
	{
		const auto d = m_plane.disparity(u, v);
		const auto s = m_plane.score(u, v, 0.0);
		if (!d || !s || s->ncc < m_o.acceptNcc || s->leftStd < m_textureGate) return std::nullopt;
		if (!peaksNearThePlane(m_plane, u, v, s->ncc)) return std::nullopt;
		const float model = m_evaluation.modelDisparity(v, u);
		if (model > 0)
		{
			const auto explained = m_plane.score(u, v, model - *d);
			if (explained && explained->ncc > s->ncc - m_o.modelMargin) return std::nullopt;
		}
		return PlaneRow{v, *d, s->ncc};
	}

	/** Follows column u from the row after the start row until the plane
	 * fails, and appends the rows kept to `grown`; `atStart`: the start
	 * row's own, where a sideways walk found the plane holding there. */
	void column(int u, std::optional<PlaneRow> atStart, std::vector<VisualPoint>& grown) const
	{
		std::vector<PlaneRow> walked;
		if (atStart) walked.push_back(*atStart);
		for (int v = m_startRow + m_step;; v += m_step)
		{
			const auto row = holds(u, v);
			if (!row) break;
			walked.push_back(*row);
		}
		// The window straddles the edge for the last half-height rows.
		const size_t halfHeight = size_t(m_o.windowHalfHeight);
		const size_t keep = walked.size() > halfHeight ? walked.size() - halfHeight : 0;
		for (size_t i = 0; i < keep; i++)
		{
			// Every stride-th row, as the search's grid, and the last one kept.
			if ((i + 1) % size_t(m_stride) != 0 && i + 1 != keep) continue;
			const PlaneRow& row = walked[i];
			const Eigen::Vector3d x = m_plane.point(u, row.v, row.disparity);
			if (m_band.contains(x.z()))
				grown.push_back({static_cast<float>(u), static_cast<float>(row.v), static_cast<float>(row.disparity),
					static_cast<float>(row.ncc), x});
		}
	}

   private:
	const PlaneWindow& m_plane;
	const lvf::evaluation::ModelEvaluation& m_evaluation;
	const HeightBand& m_band;
	const HorizontalSurfaceGrowth::TOptions& m_o;
	double m_textureGate;
	int m_stride, m_startRow, m_step;
};
}  // namespace

void HorizontalSurfaceGrowth::walk(
	const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& g,
	const lvf::evaluation::ModelEvaluation& evaluation, const HeightBand& band, double textureGate, int stride,
	int u, const VisualPoint& start, int step, WalkedColumns& walked, std::vector<VisualPoint>& grown) const
{
	const TOptions& o = m_options;
	const PlaneWindow plane(
		left, right, g, fittedHeight(left, right, g, u, start, step, stride), o.windowHalfWidth, o.windowHalfHeight);
	const SurfaceWalk surface(plane, evaluation, band, o, textureGate, stride, static_cast<int>(start.v), step);
	surface.column(u, std::nullopt, grown);
	if (!o.sideways) return;
	// Along the start row, a grid column at a time each way, up to a column
	// already followed; the last columns whose window reaches past the
	// surface's side (half a window) are dropped, as the rows at its edge.
	const int straddling = (o.windowHalfWidth + stride - 1) / stride;
	for (const int direction : {-1, 1})
	{
		std::vector<std::pair<int, PlaneRow>> side;
		for (int c = u + direction * stride; !walked.count({c, step}); c += direction * stride)
		{
			const auto row = surface.holds(c, surface.startRow());
			if (!row) break;
			side.push_back({c, *row});
		}
		for (size_t i = 0; i + size_t(straddling) < side.size(); i++)
		{
			walked.insert({side[i].first, step});
			surface.column(side[i].first, side[i].second, grown);
		}
	}
}

size_t HorizontalSurfaceGrowth::grow(
	const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& g,
	const lvf::evaluation::ModelEvaluation& evaluation, const HeightBand& band, double textureGate, int stride,
	std::vector<VisualPoint>& points) const
{
	if (!m_options.enabled) return 0;
	const double cameraHeight = g.leftPose.z();
	std::map<int, std::vector<size_t>> byColumn;
	for (size_t i = 0; i < points.size(); i++) byColumn[static_cast<int>(std::lround(points[i].u))].push_back(i);

	// A surface below the camera comes nearer down the image, one above it
	// up the image: one walk each way per column, from the column's nearest
	// point with a witness.
	struct Start
	{
		int u;
		const VisualPoint* point;
		int step;
	};
	std::vector<Start> starts;
	WalkedColumns walked;
	for (auto& [u, indices] : byColumn)
	{
		std::sort(indices.begin(), indices.end(), [&](size_t a, size_t b) { return points[a].v < points[b].v; });
		for (const int step : {1, -1})
		{
			const bool below = step > 0;
			for (size_t k = 0; k < indices.size(); k++)
			{
				const VisualPoint& p = points[indices[below ? indices.size() - 1 - k : k]];
				if ((p.robot.z() < cameraHeight) != below || !hasWitness(p, points, indices, step, stride)) continue;
				starts.push_back({u, &p, step});
				walked.insert({u, step});
				break;
			}
		}
	}
	std::vector<VisualPoint> grown;
	for (const Start& s : starts)
		walk(left, right, g, evaluation, band, textureGate, stride, s.u, *s.point, s.step, walked, grown);
	points.insert(points.end(), grown.begin(), grown.end());
	return grown.size();
}

}  // namespace lvf::depth
