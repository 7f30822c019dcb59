// SPDX-License-Identifier: MIT
// The one search of the free shapes' parameters (a skew's law, a knee's law, a ripple's period,
// a settling's curvature, a mains line's frequency, a held-out session's age): the least of an
// objective over a lattice of points, then, where the family asks for it, a pattern refinement
// with shrinking steps from the best point. Points are tried in the order given and a point is
// taken only when its value is strictly less than the best so far, so ties go to the earlier.
#pragma once

#include <functional>
#include <limits>
#include <optional>
#include <vector>

namespace flange::diagnose::free_shapes {

using Objective = std::function<double(const std::vector<double>& at)>;

// The best point so far and its value (infinite until a point is tried: a search whose every
// value is infinite or not a number leaves the point it started from).
struct SearchPoint {
  std::vector<double> at;
  double value = std::numeric_limits<double>::infinity();
};

// One axis of a lattice: lo, lo + step, lo + 2 step, ... (each the one before plus step) while
// not above hi.
std::vector<double> stepped_axis(double lo, double hi, double step);

// Every point of the lattice over `axes`, the first axis outermost.
std::vector<std::vector<double>> lattice(const std::vector<std::vector<double>>& axes);

// Each of `points` in turn: `best` moves to a point whose value is strictly less than its own.
void search_points(const std::vector<std::vector<double>>& points, const Objective& value,
                   SearchPoint& best);

// search_points with the points' values worked out over the worker threads (parallel_work.h)
// and then taken in the order given: the same point as search_points, for an objective that
// writes nothing it shares (a family that keeps its state in the objective uses search_points).
void search_points_at_once(const std::vector<std::vector<double>>& points, const Objective& value,
                           SearchPoint& best);

// One move of a pattern search: from the point `from` by `step`, the point to try, or nothing
// where the move leaves the search's domain.
using PatternMove =
    std::function<std::optional<std::vector<double>>(const std::vector<double>& from, double step)>;

// Each of `dims` coordinates down by the step, then up.
std::vector<PatternMove> coordinate_moves(std::size_t dims);

// For each of `steps` in turn, passes over `moves` until one moves nothing: each move is made
// from the best point at the time it is tried, and `best` moves to its point when that is
// strictly less.
void refine_by_pattern(const std::vector<double>& steps, const std::vector<PatternMove>& moves,
                       const Objective& value, SearchPoint& best);

// The lattice, then the pattern refinement from its best point.
SearchPoint grid_search(const std::vector<std::vector<double>>& points,
                        const std::vector<double>& steps, const std::vector<PatternMove>& moves,
                        const Objective& value, SearchPoint start);

}  // namespace flange::diagnose::free_shapes
