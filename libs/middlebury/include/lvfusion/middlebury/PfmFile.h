#pragma once
// Single-channel PFM images ("Pf"), as Middlebury stores ground-truth
// disparity: a text header (width, height, scale whose sign gives the byte
// order) and float32 rows stored bottom to top.
//
// Read by hand rather than with cv::imread: OpenCV 4.6's decoder multiplies
// every value by 1 / |scale|, and these files carry scale -0.003922 (-1/255),
// so cv::imread returns disparities 255 times too large; and on a truncated
// file it prints an OpenCV warning of its own to stderr and returns an empty
// image, without naming what is missing.

#include <opencv2/core/mat.hpp>

#include <string>

namespace lvf::middlebury
{
/** Returns a CV_32FC1 image, rows top to bottom (row 0 = top of the picture),
 * values as stored (inf where Middlebury's disparity is unknown). Throws
 * InputError naming the file and the header field or "pixel data". */
cv::Mat readPfm(const std::string& path);

}  // namespace lvf::middlebury
