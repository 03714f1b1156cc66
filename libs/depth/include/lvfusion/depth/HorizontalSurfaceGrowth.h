#pragma once
// Stage 4b: horizontal surfaces (table tops, box tops seen from above)
// followed towards the camera, beyond where the focused search finds them.
//
// The search's square windows assume a surface facing the camera. On a
// horizontal plane h below (or above) the camera the disparity changes by
// about fB / (f |h|) per image row -- 0.5 px a row for a table top 0.25 m
// under the camera -- so an 11-row window spans 5 px of disparity there and
// matches only where the texture happens to allow it: the search finds a
// top, but well behind its front edge (seeded room 5: 0.1-0.45 m behind),
// and a bearing's range comes out too far.
//
// This stage takes the search's own evidence of a horizontal surface -- two
// accepted points on one image column at the same height, the one nearer the
// image's edge also nearer the robot -- and follows that plane z = h along
// the column, row by row, away from the horizon (its height fitted to the
// images near the start, within a few cm). No search: at each row a
// window is matched once, each of its rows at the disparity the plane gives
// that row (a sheared window); it must score `accept_ncc`, peak within a
// pixel of the plane's disparity (the best of the plane and the plane
// shifted by 1 px beating it shifted by 2 px), and beat the scene model's
// own disparity there by `model_margin` (else the floor or a wall explains
// it as well). The walk stops at the first row that fails. A window centred
// up to half its height past the surface's edge still lies mostly on it and
// matches, so the last `window_half_height` rows are dropped. The rows kept
// become visual points every pixel_stride rows, like the search's grid.
//
// Far out the search finds such a surface on a few columns only; the walk
// also goes sideways along its start row (`sideways`), a grid column at a
// time while the plane holds there, and follows each of those columns to the
// edge in the same way: the front edge need not run along an image row. The
// last columns whose window reaches past the surface's side are dropped,
// and no column is followed twice.

#include <lvfusion/common/HeightBand.h>
#include <lvfusion/depth/FocusedEpipolarSearch.h>
#include <lvfusion/evaluation/ModelEvaluator.h>
#include <lvfusion/evaluation/RectifiedStereo.h>
#include <mrpt/config/CLoadableOptions.h>

#include <set>
#include <utility>
#include <vector>

namespace lvf::depth
{
class HorizontalSurfaceGrowth
{
   public:
	/** INI section [HorizontalSurfaceGrowth]. */
	struct TOptions : public mrpt::config::CLoadableOptions
	{
		bool enabled = true;
		/** Also along the row: from each walk's start, grid column by grid
		 * column sideways while the plane holds on the start row, each
		 * column then walked to the edge as its own. A table top seen 3-5 m
		 * out, nearly edge-on, gives the search a few columns of points;
		 * the rows between them are the same plane. Measured with the
		 * fusion's range rules of 2026-12-03 (ScanFusion.h; recall /
		 * phantom rate, off -> on): corridor desk 0.785 -> 0.805, 0.007
		 * both; 60 seeded rooms (1-6 ... 91-96), rooms 201-230 and
		 * Middlebury unchanged; a top 3 m out
		 * (test_horizontal_surface_growth) 0.381 -> 0.476. A first version
		 * that walked columns other walks had followed too counted their
		 * points twice: more recall (60 rooms 0.861), more phantoms. */
		bool sideways = true;
		/** Each row's sheared window must score this. Measured (seeded
		 * rooms 1-6 / 31-36, corridor desk): 0.9 with a back-off of 3 rows
		 * on a 7-row window gave the same recall as 0.95 and one phantom
		 * bearing more in rooms 1-6. */
		double acceptNcc = 0.95;
		int windowHalfWidth = 5;  //!< [px]: 11 columns, as the search's window
		/** [px]: 5 rows. Taller windows (7 rows) found fewer bearings
		 * (rooms 1-6: 0.838 against 0.849, corridor desk 0.595 against
		 * 0.630), the same phantoms. */
		int windowHalfHeight = 2;
		/** The plane must beat the model's own disparity by this NCC. */
		double modelMargin = 0.05;
		/** [m]. A triangulated point's height is off by 1-3 cm at 2.5 m,
		 * which puts the plane's disparity 1-2 px off on a top 0.25 m under
		 * the cameras, and the walk stops at its first row. The plane's
		 * height is fitted instead: the best summed NCC of the sheared window
		 * at the start row and two grid rows behind it, over heights within
		 * this of the start point's (measured, against the point's own
		 * height: rooms 1-6 0.845 -> 0.859, 21-26 0.698 -> 0.705, 31-36
		 * 0.821 -> 0.813, corridor desk 0.630 -> 0.660, the same phantoms;
		 * fitted at the start row alone: 31-36 the same, 21-26 one phantom
		 * bearing more). */
		double heightSearch = 0.02;
		/** Two points are on one horizontal surface when their heights differ
		 * by at most this [m]... */
		double heightTolerance = 0.03;
		/** ...and the one nearer the image's edge is at least this much
		 * nearer the robot [m]. */
		double minRangeStep = 0.02;
		/** ...and at most this many grid strides apart on the column. */
		int witnessStrides = 4;
		/** ...and their heights differ by at most this fraction of their
		 * ranges' difference. Down a horizontal surface's column the range changes fast
		 * and the height by noise only; down a vertical one (a table leg, a
		 * box's side) the height changes by a pixel's worth a row and the
		 * range by noise, which can pass the two bounds above: a back leg's
		 * foot 2.4 m out, two points 6 rows apart 2.5 cm apart in height and
		 * 2.4 cm in range, started a walk at 6 cm over the floor (seen with
		 * 9-pixel windows), and took its column's walk from the top above.
		 * Measured, off -> 0.5 (recalled / phantom bearings): corridor desk
		 * 166 / 4 -> 170 / 4, rooms 301-340 1,591 / 99 -> 1,594 / 99, the 60
		 * rooms 2,579 / 126 -> 2,578 / 125; rooms 1-6 and 201-230, box room,
		 * Middlebury unchanged. 1.0: corridor 166, 301-340 1,593; 0.3: as
		 * 0.5 but 301-340 1,595. */
		double maxSlope = 0.5;

		void loadFromConfigFile(
			const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void saveToConfigFile(
			mrpt::config::CConfigFileBase& target, const std::string& section) const override;
	};

	explicit HorizontalSurfaceGrowth(const TOptions& options) : m_options(options) {}

	/** Appends the grown points to `points` (the search's accepted points,
	 * read as the evidence) and returns how many it added. `textureGate`:
	 * the search's (a window flatter than this carries no evidence).
	 * `stride`: the search's pixel_stride. */
	size_t grow(
		const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& g,
		const lvf::evaluation::ModelEvaluation& evaluation, const HeightBand& band, double textureGate,
		int stride, std::vector<VisualPoint>& points) const;

	const TOptions& options() const { return m_options; }

   private:
	/** Another point of the column behind `p` as the walk goes (`step`,
	 * +1 or -1, is the walk's direction down the rows), at most
	 * witness_strides grid strides away, on the same height and farther
	 * from the robot. */
	bool hasWitness(
		const VisualPoint& p, const std::vector<VisualPoint>& points, const std::vector<size_t>& column, int step,
		int stride) const;
	/** The height of the plane through `start` that fits the images best
	 * (heightSearch above). */
	double fittedHeight(
		const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& g, int u,
		const VisualPoint& start, int step, int stride) const;
	/** Height steps of that fit [m]: about 0.4 px of disparity at 2.5 m on
	 * a top 0.25 m under the cameras. */
	static constexpr double kHeightSearchStep = 0.005;
	/** Columns (u, step) a walk has followed, or will from its own start. */
	using WalkedColumns = std::set<std::pair<int, int>>;
	/** Follows the plane through `start` along column u, rows `step` at a
	 * time, and (with `sideways`) along its row into the columns not in
	 * `walked`, which it adds; appends the rows kept to `grown`. */
	void walk(
		const cv::Mat1b& left, const cv::Mat1b& right, const lvf::evaluation::RectifiedGeometry& g,
		const lvf::evaluation::ModelEvaluation& evaluation, const HeightBand& band, double textureGate, int stride,
		int u, const VisualPoint& start, int step, WalkedColumns& walked, std::vector<VisualPoint>& grown) const;

	TOptions m_options;
};

}  // namespace lvf::depth
