#pragma once
// Moving a window of image rows down an image: the row-wise window sums of
// the model check (GridWindowSums) and of the search's statistics
// (WindowStatistics) keep per-column sums over the rows of the current
// window and slide them from one grid row to the next.

namespace lvf::common
{
/** Moves the (2 half + 1)-row window centred on row `from` (negative: no
 * window yet) to the one centred on `to`. Where the two overlap and `to`
 * lies below, calls add(y, -1) for each row that leaves and add(y, +1) for
 * each that enters; otherwise clear(), then add(y, +1) for every row of the
 * new window. Nothing when `to` is `from`. */
template <typename Clear, typename Add>
void slideWindowRows(int from, int to, int half, Clear clear, Add add)
{
	if (to == from) return;
	if (from >= 0 && to > from && to - from <= 2 * half)
	{
		for (int y = from - half; y < to - half; y++) add(y, -1);
		for (int y = from + half + 1; y <= to + half; y++) add(y, +1);
		return;
	}
	clear();
	for (int y = to - half; y <= to + half; y++) add(y, +1);
}

}  // namespace lvf::common
