#pragma once
// Cost-to-go by value iteration (Bellman 1957; the paper's ref. [13]).
//
// States are the traversable cells; actions the 8 moves to a neighbour, each
// deterministic with cost = its length (res or res*sqrt(2)); a diagonal move
// is allowed only when both cells it cuts past are traversable. The goal is
// absorbing with V(goal) = 0. Value iteration applies the Bellman update
//
//     V(s) <- min over moves a to a traversable s' of [ cost(a) + V(s') ]
//
// to every state until V stops changing, starting from V = +inf (unknown
// cost) everywhere but the goal. Values only ever decrease, and each equals
// the length of some path to the goal, so they converge in finitely many
// sweeps to the optimal cost-to-go on the 8-connected grid; cells that keep
// +inf cannot reach the goal.
//
// Efficiency: the updates are done in place (Gauss-Seidel: a new value is
// used at once by its neighbours), sweeping the grid in the four raster
// orders in turn (the "fast sweeping" schedule). A sweep carries values along
// its own direction across the whole grid, so open maps converge in a handful
// of sweeps and every extra bend of the optimal paths costs a few more. The
// loop stops after the first sweep in which no value changed by more than
// `tolerance`: then the Bellman update is the identity on every state, i.e. V
// is its fixed point (with tolerance 0, exactly).

#include <lvfusion/planning/TraversableGrid.h>

#include <array>
#include <cstddef>

namespace lvf::planning
{
/** One of the 8 moves to a neighbouring cell, and its length [m]. */
struct GridMove
{
	int dx, dy;
	float cost;
};

/** The 8 moves on cells of `resolution` [m], row by row from (-1, -1): the
 * value function and the descent along it must price them alike. */
std::array<GridMove, 8> gridMoves(float resolution);

/** Whether the cell (x, y) may take `move`, `free(x, y)` telling which
 * cells are traversable: to a free neighbour, and for a diagonal only past
 * two free side cells (no corner cutting). (x, y) itself is not tested. */
template <typename Free>
bool moveAllowed(const Free& free, int x, int y, const GridMove& move)
{
	if (!free(x + move.dx, y + move.dy)) return false;
	return !(move.dx && move.dy) || (free(x + move.dx, y) && free(x, y + move.dy));
}

struct ValueFunction
{
	cv::Mat1f value;  //!< cost-to-go [m] per cell, +inf: unreachable or obstacle
	size_t sweeps = 0;	//!< Gauss-Seidel sweeps run
	bool converged = false;	 //!< the last sweep changed nothing (beyond tolerance)
	double lastChange = 0;	//!< largest value change in the last sweep [m]
};

/** Value iteration towards `goal` (must be traversable) on `grid`. */
ValueFunction computeValueFunction(
	const TraversableGrid& grid, const GridCell& goal, size_t maxSweeps, double tolerance);

}  // namespace lvf::planning
