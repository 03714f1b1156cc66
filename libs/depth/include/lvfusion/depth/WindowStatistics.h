#pragma once
// The mean and standard deviation of every (2 half + 1)^2 window of an image
// (MatchingLevel's per-frame statistics, which the NCC scores divide by).

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace lvf::depth
{
/** Rows first, first + step, first + 2 step, ... of an image; with
 * `wanted` (one flag per image row), only those of them it flags. */
struct RowGrid
{
	int first = 0, step = 1;
	std::vector<uint8_t> wanted;
	bool all() const { return first == 0 && step == 1 && wanted.empty(); }
	bool isWanted(int v) const { return wanted.empty() || wanted[static_cast<size_t>(v)]; }
};

/** Window mean and deviation at every pixel of a grey `image` (box filters
 * in float, border reflected); with a row grid, only at the grid's rows and
 * only where a whole window fits (columns and rows half .. size - 1 - half)
 * -- every other value is left undefined. The grid's values are those of the
 * whole image bit for bit: its window sums are integers, exact in any order
 * in float (up to 15 x 15 windows), and scaled and
 * combined as OpenCV's blur and sqrBoxFilter do (checked by
 * test_visual_depth; no product is fused into a sum on the default
 * x86-64 target, as in EpipolarScores' score formula). The focused search
 * reads the full resolution's statistics only on its pixel grid, a third
 * of the rows at the default stride (0.90 -> 0.43 ms per 640x480 frame),
 * and the half resolution's where a window fits (0.67 -> 0.52 ms for both
 * images: OpenCV's six whole-image passes cost more at 320x240). */
void windowStatistics(const cv::Mat1b& image, int half, const RowGrid& rows, cv::Mat1f& mean, cv::Mat1f& deviation);

}  // namespace lvf::depth
