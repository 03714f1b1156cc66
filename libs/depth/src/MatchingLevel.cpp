#include <lvfusion/depth/CrossTerms.h>
#include <lvfusion/depth/MatchingLevel.h>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <mutex>
#include <vector>

namespace lvf::depth
{
namespace
{
/** Half resolution, in whole grey levels like the full one: the cross terms
 * multiply 16-bit integers (CrossTerms.h), and the window statistics' sums
 * are integers, exact in float whatever the order of their additions.
 * Filtered as 8 bits: filtering float copies and rounding afterwards gave
 * the same image but for the 0.2 % of pixels whose value is a grey level and
 * a half (rounded to even there, up here), and converting both images to
 * float for it took 8 % of the fusion's time on the seeded rooms. */
cv::Mat1b pyramidDown(const cv::Mat1b& image)
{
	cv::Mat1b grey;
	cv::pyrDown(image, grey);
	return grey;
}
}  // namespace

struct MatchingLevel::Images
{
	/** The grey images themselves (shared, not copied): the neighbour pairs,
	 * the window statistics and the sub-pixel steps all read whole grey
	 * levels. */
	Images(const cv::Mat1b& l, const cv::Mat1b& r, int h, RowGrid grid)
		: half(h), left(l), right(r), leftPairs(neighbourPairs(l)),
		  rightPairs(neighbourPairs(r)), rows(std::move(grid))
	{
		windowStatistics(right, half, rows, rightMean, rightStd);
	}

	/** The left image's statistics are computed on first use, by whichever
	 * thread asks first: the full level of a coarse-to-fine search takes its
	 * pixels' statistics from the evaluation and checks left-right on the
	 * coarse level, so it mostly never needs them (0.7 ms of a box-room
	 * frame). */
	void needLeftStatistics()
	{
		std::call_once(leftStatisticsDone, [this] { windowStatistics(left, half, rows, leftMean, leftStd); });
	}

	const int half;
	const cv::Mat1b left, right;
	const cv::Mat1i leftPairs, rightPairs;
	cv::Mat1f rightMean, rightStd;
	const RowGrid rows;
	std::once_flag leftStatisticsDone;
	cv::Mat1f leftMean, leftStd;
};

MatchingLevel::MatchingLevel(std::shared_ptr<Images> images)
	: m_images(std::move(images)),
	  half(m_images->half),
	  left(m_images->left),
	  right(m_images->right),
	  leftPairs(m_images->leftPairs),
	  rightPairs(m_images->rightPairs),
	  rightMean(m_images->rightMean),
	  rightStd(m_images->rightStd),
	  forward(leftPairs, rightPairs, rightMean, rightStd, half),
	  shifted(leftPairs, rightPairs, rightMean, rightStd, half),
	  m_backward(rightPairs, leftPairs, m_images->leftMean, m_images->leftStd, half)
{
}

MatchingLevel::MatchingLevel(const cv::Mat1b& l, const cv::Mat1b& r, int h, RowGrid rows)
	: MatchingLevel(std::make_shared<Images>(l, r, h, std::move(rows)))
{
}

namespace
{
/** The half-resolution rows under a finer level's rows: coarse row v / 2
 * for each of its grid rows it computes statistics on (every row where a
 * window fits when the finer level has them all). */
RowGrid rowsUnder(const RowGrid& finer, int finerRows, int half)
{
	if (finer.all()) return RowGrid{half, 1, {}};
	std::vector<uint8_t> wanted(static_cast<size_t>((finerRows + 1) / 2), 0);  // cv::pyrDown's rows
	for (int v = std::max(finer.first, 0); v < finerRows; v += finer.step)
		if (finer.isWanted(v)) wanted[static_cast<size_t>(v / 2)] = 1;
	return RowGrid{half, 1, std::move(wanted)};
}
}  // namespace

MatchingLevel::MatchingLevel(const MatchingLevel& finer, int h)
	// Only the rows under the finer level's (only those are matched from):
	// the same values, and on a 320x240 level faster than OpenCV's filters.
	: MatchingLevel(std::make_shared<Images>(pyramidDown(finer.left), pyramidDown(finer.right), h,
		  rowsUnder(finer.m_images->rows, finer.left.rows, h)))
{
}

MatchingLevel::~MatchingLevel() = default;

std::unique_ptr<MatchingLevel> MatchingLevel::forAnotherThread() const
{
	return std::unique_ptr<MatchingLevel>(new MatchingLevel(m_images));
}

void MatchingLevel::prepareLeftStatistics() { m_images->needLeftStatistics(); }

EpipolarScores& MatchingLevel::backward()
{
	m_images->needLeftStatistics();
	return m_backward;
}

float MatchingLevel::leftMeanAt(int v, int u)
{
	m_images->needLeftStatistics();
	return m_images->leftMean(v, u);
}

float MatchingLevel::leftStdAt(int v, int u)
{
	m_images->needLeftStatistics();
	return m_images->leftStd(v, u);
}

}  // namespace lvf::depth
