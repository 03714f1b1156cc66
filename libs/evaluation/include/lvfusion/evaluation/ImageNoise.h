#pragma once
// How much of a grey image's variation is sensor noise: the texture gates of
// the evaluation and the search are set relative to it, since "too little
// texture to match" means "not much more than the noise". An absolute gate
// fitted to one camera misjudges another: 4 grey levels keeps the
// simulator's noise (std 2) from being judged, and leaves most of a smooth
// but clean real surface (Middlebury's downscaled images) unsearched.
//
// Immerkaer's estimator (1996): the 3x3 kernel
//   1 -2  1 / -2  4 -2 / 1 -2  1
// (a difference of two Laplacians) cancels smooth image structure; on iid
// Gaussian noise of std s its response has std 6 s. Immerkaer takes the mean
// absolute response; texture edges inflate that (a richly textured
// Middlebury scene reads 2.7 grey levels against 0.8 for a plain one), so
// here it is the median absolute response, scaled for Gaussian noise
// (s = 1.4826 median / 6): 2.22 on the simulator's std-2 noise, every frame.

#include <opencv2/core.hpp>

#include <algorithm>

namespace lvf::evaluation
{
/** Noise std of `image` [grey levels], from every `rowStep`-th row (the
 * median needs far fewer than all of them). */
double estimateNoiseStd(const cv::Mat1b& image, int rowStep = 4);

/** A texture gate of `ratio` times the noise, and at least `floor` [grey
 * levels]: the evaluation's and the search's gates alike. */
inline double noiseRelativeGate(double noiseStd, double ratio, double floor)
{
	return std::max(floor, ratio * noiseStd);
}

}  // namespace lvf::evaluation
