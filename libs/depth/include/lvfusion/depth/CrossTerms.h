#pragma once
// The cross term of the NCC -- the sum over a window of left x right grey
// levels -- for one left window against a stretch of right columns: most of
// the focused search's arithmetic (~6 * 10^7 products per 640x480 frame).
//
// Both matching levels hold grey images (0..255; the half-resolution one is
// cv::pyrDown's 8-bit one), so the products are 16-bit integers and the sums
// exact 32-bit ones. The images are kept as "neighbour pairs": pixel x and
// pixel x + 1 of a row as two 16-bit integers in one 32-bit word. One AVX2
// multiply-add (vpmaddwd) then takes two window columns of eight right
// columns at once -- sixteen products for one instruction and one load,
// where float vectors took eight for a multiply, an add and a load (the
// box-room search in lvf-bench: 9.5 -> 8.3-9.2 ms a frame, alternated with
// the float version). Integers are exact in any order, so every CPU and
// every path gives the same sums, and, below 2^24, the same floats as
// summing in float did: the search decides exactly as before.

#include <opencv2/core.hpp>

#include <cstdint>

namespace lvf::depth
{
/** Each pixel of a whole-grey-level image with its right neighbour: word
 * (v, x) holds image(v, x) in its low 16 bits and image(v, x + 1) in its
 * high ones (0 past the last column). */
cv::Mat1i neighbourPairs(const cv::Mat1b& image);

/** The grey level of a neighbour-pair word's own pixel. */
inline int32_t pixelOf(int32_t pair) { return pair & 0xFFFF; }

/** acc[i] = sum over the (2 half + 1)^2 window of left(u + dx, v + dy) x
 * right(x0 + i + dx, v + dy), i < n, from the two images' neighbour pairs;
 * every window inside both images. */
void crossTerms(
	const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, int u, int v, int x0, int n, int half,
	int32_t* acc);

/** The same one product at a time, on any CPU: the reference the vector
 * path is tested against, and the path where there is no AVX2. */
void crossTermsPlain(
	const cv::Mat1i& leftPairs, const cv::Mat1i& rightPairs, int u, int v, int x0, int n, int half,
	int32_t* acc);

}  // namespace lvf::depth
