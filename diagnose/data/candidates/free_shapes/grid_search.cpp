// SPDX-License-Identifier: MIT
#include "grid_search.h"

#include <utility>

#include "parallel_work.h"

namespace flange::diagnose::free_shapes {

std::vector<double> stepped_axis(double lo, double hi, double step) {
  std::vector<double> values;
  for (double x = lo; x <= hi; x += step) values.push_back(x);
  return values;
}

std::vector<std::vector<double>> lattice(const std::vector<std::vector<double>>& axes) {
  std::vector<std::vector<double>> points = {{}};
  for (const std::vector<double>& axis : axes) {
    std::vector<std::vector<double>> longer;
    for (const std::vector<double>& point : points) {
      for (double x : axis) {
        longer.push_back(point);
        longer.back().push_back(x);
      }
    }
    points = std::move(longer);
  }
  return points;
}

namespace {

// Tries `at`: whether it became the best.
bool try_point(const std::vector<double>& at, const Objective& value, SearchPoint& best) {
  const double v = value(at);
  if (!(v < best.value)) return false;
  best.value = v;
  best.at = at;
  return true;
}

}  // namespace

void search_points(const std::vector<std::vector<double>>& points, const Objective& value,
                   SearchPoint& best) {
  for (const std::vector<double>& at : points) try_point(at, value, best);
}

void search_points_at_once(const std::vector<std::vector<double>>& points, const Objective& value,
                           SearchPoint& best) {
  const std::vector<double> values =
      parallel_map<double>(points.size(), [&](std::size_t i) { return value(points[i]); });
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!(values[i] < best.value)) continue;
    best.value = values[i];
    best.at = points[i];
  }
}

std::vector<PatternMove> coordinate_moves(std::size_t dims) {
  std::vector<PatternMove> moves;
  for (std::size_t k = 0; k < dims; ++k) {
    for (double sign : {-1.0, 1.0}) {
      moves.push_back([k, sign](const std::vector<double>& from, double step) {
        std::vector<double> to = from;
        to[k] += sign * step;
        return std::optional<std::vector<double>>(std::move(to));
      });
    }
  }
  return moves;
}

void refine_by_pattern(const std::vector<double>& steps, const std::vector<PatternMove>& moves,
                       const Objective& value, SearchPoint& best) {
  for (double step : steps) {
    for (bool moved = true; moved;) {
      moved = false;
      for (const PatternMove& move : moves) {
        if (const std::optional<std::vector<double>> to = move(best.at, step)) {
          moved = try_point(*to, value, best) || moved;
        }
      }
    }
  }
}

SearchPoint grid_search(const std::vector<std::vector<double>>& points,
                        const std::vector<double>& steps, const std::vector<PatternMove>& moves,
                        const Objective& value, SearchPoint start) {
  search_points(points, value, start);
  refine_by_pattern(steps, moves, value, start);
  return start;
}

}  // namespace flange::diagnose::free_shapes
