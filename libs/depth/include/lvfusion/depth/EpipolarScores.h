#pragma once
// NCC of one left-image window against the right-image windows along its
// epipolar line (the same row of the rectified pair), computed on demand and
// cached, so that the search, the peak test and the verifications never score
// a column twice. Window means and variances come from box filters; only the
// cross term is summed per column. Written by hand because OpenCV's
// matchTemplate (TM_CCOEFF_NORMED) costs 3-4x more here: its per-call set-up
// dominates for one 11x11 window against a strip of a few dozen columns.

#include <opencv2/core.hpp>

#include <vector>

namespace lvf::depth
{
class EpipolarScores
{
   public:
	/** All images float; means and variances over the (2 half + 1)^2 window. */
	EpipolarScores(
		const cv::Mat1f& left, const cv::Mat1f& right, const cv::Mat1f& rightMean,
		const cv::Mat1f& rightVariance, int half);

	/** Starts a new left pixel, whose window has this mean and std. */
	void reset(int u, int v, float leftMean, float leftStd);
	/** Scores right columns [x0, x1], clipped to where a window fits. */
	void compute(int x0, int x1);
	/** Score of column x (computed on demand); -2 outside the image. */
	float at(int x);

	int firstColumn() const { return m_half; }
	int lastColumn() const { return m_right.cols - 1 - m_half; }
	size_t evaluations() const { return m_evaluations; }

   private:
	const cv::Mat1f& m_left;
	const cv::Mat1f& m_right;
	const cv::Mat1f& m_rightMean;
	const cv::Mat1f& m_rightVariance;
	int m_half, m_u = 0, m_v = 0;
	float m_leftMean = 0, m_leftStd = 1;
	std::vector<float> m_scores;  // NaN: not computed yet
	std::vector<int> m_touched;	 // columns to clear on reset
	std::vector<float> m_cross;	 // scratch: cross terms of a stretch
	size_t m_evaluations = 0;
};

}  // namespace lvf::depth
