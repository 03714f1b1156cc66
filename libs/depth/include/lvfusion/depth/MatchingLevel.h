#pragma once
// One resolution of the rectified pair, ready for window matching along rows:
// the grey images, the window mean and deviation of every pixel of both, or of
// the rows it will match from (WindowStatistics.h; once per frame, the left
// image's when first asked for), both images as neighbour pairs for the
// cross terms' integer multiply-adds (CrossTerms.h), and an EpipolarScores
// each way (left windows against the right row for the search, right
// windows against the left row for the left-right check). The focused
// search keeps one at full resolution and, for coarse-to-fine matching, one
// at half resolution.
//
// The images and statistics are read-only once made and can be shared:
// forAnotherThread() gives a view of the same level with scores of its own,
// so that the search's threads match on one copy of the images.

#include <lvfusion/depth/EpipolarScores.h>
#include <lvfusion/depth/WindowStatistics.h>
#include <opencv2/core.hpp>

#include <memory>

namespace lvf::depth
{
class MatchingLevel
{
	/** What the threads' views share (MatchingLevel.cpp). */
	struct Images;
	std::shared_ptr<Images> m_images;

   public:
	/** Grey images, and the half side of the square matching window. With
	 * `rows`, the window statistics only on those rows (where a window
	 * fits), the only ones this level will be asked to match from. */
	MatchingLevel(const cv::Mat1b& left, const cv::Mat1b& right, int half, RowGrid rows = {});
	/** The same pair at half resolution (Gaussian pyramid), windows of half
	 * the side: a window there covers about the same scene. Statistics on
	 * the rows under the finer level's statistics rows (row v / 2 for its
	 * row v), where a window fits. */
	MatchingLevel(const MatchingLevel& finer, int half);
	MatchingLevel(const MatchingLevel&) = delete;
	MatchingLevel& operator=(const MatchingLevel&) = delete;
	~MatchingLevel();

	/** The same level, for matching on another thread: the images and the
	 * statistics are this one's (shared; the left image's computed once
	 * for all views), the scores its own. */
	std::unique_ptr<MatchingLevel> forAnotherThread() const;

	const int half;
	const cv::Mat1b &left, &right;
	const cv::Mat1i &leftPairs, &rightPairs;  //!< both as neighbour pairs (CrossTerms.h)
	const cv::Mat1f &rightMean, &rightStd;
	EpipolarScores forward;	 //!< a left window against the right row
	/** Another left window against the right row: a window shifted beside
	 * the one `forward` holds (FocusedEpipolarSearch's shifted windows). */
	EpipolarScores shifted;

	/** A right window against the left row (the left-right check). */
	EpipolarScores& backward();
	/** Computes the left image's statistics now rather than on first use:
	 * before threads share the level, so that none waits for another. */
	void prepareLeftStatistics();
	/** The left image's window mean and deviation at (v, u). */
	float leftMeanAt(int v, int u);
	float leftStdAt(int v, int u);

   private:
	explicit MatchingLevel(std::shared_ptr<Images> images);

	EpipolarScores m_backward;
};

}  // namespace lvf::depth
