#include <lvfusion/planning/ValueFunction.h>

#include <array>
#include <cmath>
#include <limits>

namespace lvf::planning
{
namespace
{
struct Move
{
	int dx, dy;
	float cost;
};

/** One in-place Bellman sweep over the padded grid in the given raster
 * order; returns the largest decrease of a value. */
float sweep(
	const cv::Mat1b& free, cv::Mat1f& v, const GridCell& goal, bool rowsUp, bool colsUp,
	const std::array<Move, 8>& moves)
{
	constexpr float inf = std::numeric_limits<float>::infinity();
	float largest = 0;
	const int rows = v.rows - 2, cols = v.cols - 2;	 // padding of one cell
	for (int i = 0; i < rows; i++)
	{
		const int y = 1 + (rowsUp ? i : rows - 1 - i);
		const uchar* f = free.ptr<uchar>(y);
		float* vy = v.ptr<float>(y);
		for (int j = 0; j < cols; j++)
		{
			const int x = 1 + (colsUp ? j : cols - 1 - j);
			if (!f[x] || (x == goal.x + 1 && y == goal.y + 1)) continue;
			float best = vy[x];
			for (const auto& m : moves)
			{
				if (!free(y + m.dy, x + m.dx)) continue;
				// No corner cutting: a diagonal needs both side cells free.
				if (m.dx && m.dy && (!free(y, x + m.dx) || !free(y + m.dy, x))) continue;
				best = std::min(best, m.cost + v(y + m.dy, x + m.dx));
			}
			if (best < vy[x])
			{
				largest = std::max(largest, vy[x] == inf ? inf : vy[x] - best);
				vy[x] = best;
			}
		}
	}
	return largest;
}
}  // namespace

ValueFunction computeValueFunction(
	const TraversableGrid& grid, const GridCell& goal, size_t maxSweeps, double tolerance)
{
	const float res = static_cast<float>(grid.resolution());
	const float diag = res * std::sqrt(2.0f);
	const std::array<Move, 8> moves{{{1, 0, res}, {-1, 0, res}, {0, 1, res}, {0, -1, res},
									 {1, 1, diag}, {1, -1, diag}, {-1, 1, diag}, {-1, -1, diag}}};
	// A one-cell border of obstacles spares the inner loop any bounds checks.
	cv::Mat1b free;
	cv::copyMakeBorder(grid.traversable(), free, 1, 1, 1, 1, cv::BORDER_CONSTANT, 0);
	cv::Mat1f v(free.size(), std::numeric_limits<float>::infinity());
	v(goal.y + 1, goal.x + 1) = 0;

	ValueFunction out;
	while (out.sweeps < maxSweeps)
	{
		const size_t order = out.sweeps++ % 4;
		out.lastChange = sweep(free, v, goal, order < 2, order % 2 == 0, moves);
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
