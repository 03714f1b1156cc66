#pragma once
// The sub-pixel column of a match, refined on the images themselves.
//
// The parabola through the NCC scores of the best column and its two
// neighbours weighs every pixel of the window alike, so a window over two
// surfaces (an object's edge, a table top's front, the floor under a box)
// puts the match between their disparities, up to a pixel off the centre
// pixel's own (seeded rooms: median 0.24 px on such windows, 0.07 px where
// the window sees one depth). This follows it with Lucas-Kanade along the
// row: Gauss-Newton on l(u) = a r(x + u) + b over the window (gain and offset,
// what NCC ignores), r linearly interpolated, each pixel weighted by a
// Gaussian around the centre, so the centre's surface decides the column.
//
// By hand: OpenCV's findTransformECC maximises the same correlation, but for a
// 2-D warp of a whole template, with per-call allocations and a binary mask
// only; this runs a few thousand times a frame on one row each. Its sums run
// four window columns at a time (GCC's vector extension, cloned for AVX2).

#include <opencv2/core.hpp>

#include <vector>

namespace lvf::depth
{
class SubpixelRefinement
{
   public:
	/** @param half the window's half side [px]; @param sigma the weights'
	 * Gaussian standard deviation [px]. */
	SubpixelRefinement(int half, double sigma);

	/** The right column matching the left pixel (u, v), from `column` (the
	 * parabola's), after at most `iterations` Gauss-Newton steps; `column`
	 * itself where the windows do not correlate positively, a step leaves
	 * the image, or the column moves more than a pixel from where the search
	 * took its tests. */
	double refine(const cv::Mat1b& left, const cv::Mat1b& right, int u, int v, double column, int iterations) const;

   private:
	/** The window's widest side the sums' fixed buffers hold [px]. */
	static constexpr int kMaxSide = 31;
	/** Window columns per vector. */
	static constexpr int kLanes = 4;

	int m_half;
	int m_paddedSide;	//!< the window's side rounded up to whole vectors
	std::vector<double> m_weights;	//!< row by row over the window, m_paddedSide a row, 0 past its side
	double m_weightSum = 0;
};

}  // namespace lvf::depth
