#include <lvfusion/planning/ValueFunction.h>

#include <array>
#include <cmath>
#include <limits>

namespace lvf::planning
{
std::array<GridMove, 8> gridMoves(float resolution)
{
	const float diag = resolution * std::sqrt(2.0f);
	return {{{-1, -1, diag}, {0, -1, resolution}, {1, -1, diag}, {-1, 0, resolution}, {1, 0, resolution},
			 {-1, 1, diag}, {0, 1, resolution}, {1, 1, diag}}};
}

namespace
{
/** Per cell (of the padded grid), a bit per move it may take (moveAllowed).
 * Computed once, so that the sweeps do not re-test traversability eight
 * times per cell and sweep. */
cv::Mat1b allowedMoves(const cv::Mat1b& free, const std::array<GridMove, 8>& moves)
{
	const auto isFree = [&](int x, int y) { return free(y, x) != 0; };
	cv::Mat1b allowed(free.size(), uchar(0));
	for (int y = 1; y + 1 < free.rows; y++)
		for (int x = 1; x + 1 < free.cols; x++)
		{
			if (!free(y, x)) continue;
			for (size_t m = 0; m < moves.size(); m++)
				if (moveAllowed(isFree, x, y, moves[m])) allowed(y, x) |= uchar(1u << m);
		}
	return allowed;
}

/** Bookkeeping that lets a sweep skip rows the Bellman update cannot change:
 * a row is re-evaluated only if it, or a row next to it, changed since its
 * own last evaluation (otherwise every one of its cells already equals its
 * best one-step lookahead). Times are evaluation counts. */
struct RowActivity
{
	std::vector<size_t> lastChange, lastEvaluation;
	size_t clock = 1;
	explicit RowActivity(int rows) : lastChange(rows, 1), lastEvaluation(rows, 0) {}
	bool needsEvaluation(int y) const
	{
		size_t newest = lastChange[y];
		if (y > 0) newest = std::max(newest, lastChange[y - 1]);
		if (y + 1 < int(lastChange.size())) newest = std::max(newest, lastChange[y + 1]);
		return newest >= lastEvaluation[y];
	}
};

/** One in-place Bellman sweep in the given raster order; returns the
 * largest decrease of a value. */
float sweep(
	const cv::Mat1b& allowed, cv::Mat1f& v, const GridCell& goal, bool rowsUp, bool colsUp,
	const std::array<GridMove, 8>& moves, RowActivity& rows)
{
	constexpr float inf = std::numeric_limits<float>::infinity();
	std::array<int, 8> offset{};  // neighbour index offsets in the padded grid
	for (size_t m = 0; m < moves.size(); m++) offset[m] = moves[m].dy * int(v.step1()) + moves[m].dx;
	float largest = 0;
	const int inner = v.rows - 2, cols = v.cols - 2;  // padding of one cell
	for (int i = 0; i < inner; i++)
	{
		const int y = 1 + (rowsUp ? i : inner - 1 - i);
		if (!rows.needsEvaluation(y)) continue;
		const size_t now = ++rows.clock;
		rows.lastEvaluation[y] = now;
		const uchar* a = allowed.ptr<uchar>(y);
		float* vy = v.ptr<float>(y);
		for (int j = 0; j < cols; j++)
		{
			const int x = 1 + (colsUp ? j : cols - 1 - j);
			unsigned bits = a[x];
			if (!bits || (x == goal.x + 1 && y == goal.y + 1)) continue;
			float best = vy[x];
			for (size_t m = 0; bits; m++, bits >>= 1)
				if (bits & 1u) best = std::min(best, moves[m].cost + vy[x + offset[m]]);
			if (best < vy[x])
			{
				largest = std::max(largest, vy[x] == inf ? inf : vy[x] - best);
				vy[x] = best;
				rows.lastChange[y] = now;
			}
		}
	}
	return largest;
}
}  // namespace

ValueFunction computeValueFunction(
	const TraversableGrid& grid, const GridCell& goal, size_t maxSweeps, double tolerance)
{
	const auto moves = gridMoves(static_cast<float>(grid.resolution()));
	// A one-cell border of obstacles spares the inner loop any bounds checks.
	cv::Mat1b free;
	cv::copyMakeBorder(grid.traversable(), free, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
	const cv::Mat1b allowed = allowedMoves(free, moves);
	cv::Mat1f v(free.size(), std::numeric_limits<float>::infinity());
	v(goal.y + 1, goal.x + 1) = 0;
	RowActivity rows(v.rows);

	ValueFunction out;
	while (out.sweeps < maxSweeps)
	{
		const size_t order = out.sweeps++ % 4;
		out.lastChange = sweep(allowed, v, goal, order < 2, order % 2 == 0, moves, rows);
		if (out.lastChange <= tolerance)
		{
			out.converged = true;
			break;
		}
	}
	out.value = v(cv::Rect(1, 1, v.cols - 2, v.rows - 2)).clone();
	return out;
}

}  // namespace lvf::planning
