#pragma once
// An image's grid rows (first, first + step, ... below end) cut into bands
// of consecutive rows for OpenCV's threads (cv::parallel_for_, its own pool:
// cv::setNumThreads sets its size, 1 runs everything on the caller's
// thread). The model check and the focused search judge each pixel on its
// own, so bands of rows are independent work; several bands per thread, so
// that a band of busy rows does not leave the other threads waiting.
// Header-only: its users (evaluation, depth) link OpenCV.

#include <opencv2/core/utility.hpp>

#include <algorithm>
#include <utility>

namespace lvf::common
{
class RowBands
{
   public:
	/** Rows first, first + step, ... below end, in at most bandsPerThread
	 * bands per thread of OpenCV's pool (one band on one thread). */
	RowBands(int first, int end, int step, int bandsPerThread)
		: m_first(first), m_step(step), m_rows(end > first ? (end - first - 1) / step + 1 : 0)
	{
		const int threads = cv::getNumThreads();
		m_bands = std::max(1, threads > 1 ? std::min(m_rows, bandsPerThread * threads) : 1);
	}

	int count() const { return m_bands; }
	/** Rows [first, end) of band b, on the grid. */
	std::pair<int, int> rows(int b) const
	{
		return {m_first + (m_rows * b / m_bands) * m_step, m_first + (m_rows * (b + 1) / m_bands) * m_step};
	}
	/** f(b, first, end) for every band, on OpenCV's threads when there are
	 * several bands, on this one otherwise. */
	template <typename F>
	void forEach(F f) const
	{
		auto run = [&](const cv::Range& range) {
			for (int b = range.start; b < range.end; b++)
			{
				const auto [first, end] = rows(b);
				f(b, first, end);
			}
		};
		if (m_bands > 1) cv::parallel_for_(cv::Range(0, m_bands), run);
		else run(cv::Range(0, 1));
	}

   private:
	int m_first, m_step, m_rows, m_bands = 1;
};

/** f(v) for every row v of [0, rows), in bands on OpenCV's threads: for
 * loops whose rows are independent and cost alike. */
template <typename F>
void forEachRow(int rows, F f)
{
	RowBands(0, rows, 1, 4).forEach([&](int, int first, int end) {
		for (int v = first; v < end; v++) f(v);
	});
}

}  // namespace lvf::common
