#include <lvfusion/depth/CrossTerms.h>
#include <lvfusion/depth/MatchingLevel.h>
#include <opencv2/imgproc.hpp>

namespace lvf::depth
{
namespace
{
cv::Mat1f asFloat(const cv::Mat1b& image)
{
	cv::Mat1f out;
	image.convertTo(out, CV_32F);
	return out;
}

/** Half resolution, rounded to whole grey levels: the cross terms multiply
 * 16-bit integers (CrossTerms.h), and the window statistics' sums are
 * integers, exact in float whatever the order of their additions. */
cv::Mat1f pyramidDown(const cv::Mat1f& image)
{
	cv::Mat1f smoothed;
	cv::pyrDown(image, smoothed);
	cv::Mat1b grey;
	smoothed.convertTo(grey, CV_8U);
	return asFloat(grey);
}
}  // namespace

MatchingLevel::MatchingLevel(cv::Mat1f l, cv::Mat1f r, int h, RowGrid rows)
	: half(h),
	  left(std::move(l)),
	  right(std::move(r)),
	  leftPairs(neighbourPairs(left)),
	  rightPairs(neighbourPairs(right)),
	  forward(leftPairs, rightPairs, rightMean, rightStd, half),
	  shifted(leftPairs, rightPairs, rightMean, rightStd, half),
	  m_rows(rows),
	  m_backward(rightPairs, leftPairs, m_leftMean, m_leftStd, half)
{
	windowStatistics(right, half, m_rows, rightMean, rightStd);
}

void MatchingLevel::needLeftStatistics()
{
	if (m_leftMean.empty()) windowStatistics(left, half, m_rows, m_leftMean, m_leftStd);
}

EpipolarScores& MatchingLevel::backward()
{
	needLeftStatistics();
	return m_backward;
}

float MatchingLevel::leftMeanAt(int v, int u)
{
	needLeftStatistics();
	return m_leftMean(v, u);
}

float MatchingLevel::leftStdAt(int v, int u)
{
	needLeftStatistics();
	return m_leftStd(v, u);
}

MatchingLevel::MatchingLevel(const cv::Mat1b& l, const cv::Mat1b& r, int h, RowGrid rows)
	: MatchingLevel(asFloat(l), asFloat(r), h, rows)
{
}

MatchingLevel::MatchingLevel(const MatchingLevel& finer, int h)
	// Every row where a window fits (only those are matched from): the
	// same values, and on a 320x240 level faster than OpenCV's filters.
	: MatchingLevel(pyramidDown(finer.left), pyramidDown(finer.right), h, RowGrid{h, 1})
{
}

}  // namespace lvf::depth
