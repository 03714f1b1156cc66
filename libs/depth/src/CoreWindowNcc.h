#pragma once
// Exact NCC of one small left window against right windows on its row, for
// the search's per-match tests (the core window, the shifted windows): a few
// columns each, so plain loops over a level's neighbour-pair images
// (CrossTerms.h), every sum an exact integer, the formula in double.

#include <lvfusion/depth/MatchingLevel.h>

#include <cstdint>

namespace lvf::depth
{
/** The sum and the sum of squares of the grey levels of a left window. */
struct WindowSums
{
	int32_t sum = 0, squares = 0;
};

/** Those of the (2 half + 1)^2 left window centred at (u, v). */
WindowSums leftWindowSums(const MatchingLevel& level, int u, int v, int half);

/** NCC of the (2 half + 1)^2 window centred at left (u, v) against right
 * windows on its row; the left window's sums taken once for all. */
class CoreWindowNcc
{
   public:
	CoreWindowNcc(const MatchingLevel& level, int u, int v, int half);

	/** Against the right window centred at column x; -1 where it is not
	 * wholly inside the image or either window is flat. */
	float at(int x) const;

   private:
	const MatchingLevel& m_level;
	int m_u, m_v, m_half;
	WindowSums m_left;
};

}  // namespace lvf::depth
