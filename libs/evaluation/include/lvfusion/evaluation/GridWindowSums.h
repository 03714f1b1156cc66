#pragma once
// The five window sums the model check's NCC needs -- of the left image L,
// of the right image warped by the model W, of L^2, W^2 and L W -- and the
// number of unverifiable pixels in the window, for the pixels of a grid
// (ModelEvaluator::evaluateGrid), as exact integers.
//
// W holds whole multiples of 1/32 grey level (warpByModel interpolates with
// cv::remap's weights k / 32 between whole grey levels, and gives 32 W as
// 16-bit integers), so every sum is an integer: the same
// values, to the last bit, as whole-image integral images in double gave
// (they were exact as well), without writing four 640x480 images of doubles
// per frame. Column sums over the window's rows are kept for the current
// grid row and slid down to the next (rows leaving subtracted, rows
// entering added); the row's prefix sums give each window's sum in two
// look-ups.

#include <opencv2/core.hpp>

#include <cstdint>
#include <vector>

namespace lvf::evaluation
{
class GridWindowSums
{
   public:
	/** The largest window side (ModelEvaluator's window_size allows no more). */
	static constexpr int kMaxWindow = 31;
	/** Sums of (2 half + 1)^2 windows, 2 half + 1 <= kMaxWindow (else
	 * std::invalid_argument); 32 W as warpByModel produces it. */
	GridWindowSums(const cv::Mat1b& left, const cv::Mat1w& warped32, const cv::Mat1b& unverifiable, int half);

	/** Prepares the windows centred on row v (rows v - half .. v + half must
	 * lie in the image); faster when v only grows. */
	void moveTo(int v);

	/** The sums of the window centred on (current row, u); W's in units of
	 * 1/32 grey level (its squares in 1/1024). */
	struct Sums
	{
		int64_t l, ll, w32, ww1024, lw32;
		int64_t unverifiable;  //!< pixels of the window without a match
	};
	Sums at(int u) const;

   private:
	static constexpr int kQuantities = 6;

	const cv::Mat1b& m_left;
	const cv::Mat1w& m_warped32;
	const cv::Mat1b& m_unverifiable;
	const int m_half;
	int m_row = -1;
	/** Per quantity, the column sums over the current window rows, then
	 * their running sums along the row (one more entry than columns):
	 * modulo 2^32, as every window's sum but W^2's lies in [0, 2^32) for
	 * windows up to kMaxWindow (L W: 31^2 x 255 x 8160 < 2^31), so the
	 * difference of two gives it exactly; W^2's in 64 bits (m_prefixWW). */
	std::vector<int32_t> m_columns[kQuantities];
	std::vector<uint32_t> m_prefix[kQuantities];	 // (W^2's left empty)
	std::vector<int64_t> m_prefixWW;
};

}  // namespace lvf::evaluation
