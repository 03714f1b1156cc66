#pragma once
// Moving a window of image rows down an image: the row-wise window sums of
// the model check (GridWindowSums) and of the search's statistics
// (WindowStatistics) keep per-column sums over the rows of the current
// window and slide them from one grid row to the next.

namespace lvf::common
{
/** Moves the (2 half + 1)-row window centred on row `from` (negative: no
 * window yet) to the one centred on `to`. Where the two overlap and `to`
 * lies below, as many rows leave as enter: calls exchange(leaving,
 * entering) for each pair, in one pass over the column sums instead of
 * two; otherwise clear(), then add(y) for every row of the new window.
 * Nothing when `to` is `from`. */
template <typename Clear, typename Add, typename Exchange>
void slideWindowRows(int from, int to, int half, Clear clear, Add add, Exchange exchange)
{
	if (to == from) return;
	if (from >= 0 && to > from && to - from <= 2 * half)
	{
		for (int k = 0; k < to - from; k++) exchange(from - half + k, from + half + 1 + k);
		return;
	}
	clear();
	for (int y = to - half; y <= to + half; y++) add(y);
}

}  // namespace lvf::common
