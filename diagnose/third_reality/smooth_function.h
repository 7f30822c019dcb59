// SPDX-License-Identifier: MIT
// A random smooth function on [0, 1]: 3 to 7 knots at random abscissae (0 and 1 always among
// them) with random values, monotone (rising or falling) or not, joined by a monotone-preserving
// cubic Hermite interpolant (Fritsch-Carlson slopes), so a monotone draw stays monotone and every
// draw is smooth (C1). Values span [-1, 1]; outside [0, 1] the end value holds. What an effect
// follows (a temperature, an age, a clearance) is mapped onto [0, 1] by the effect.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "third_random.h"

namespace flange::third_reality {

using Params = std::map<std::string, double>;

struct SmoothFunction {
  std::vector<double> x, y;   // knots, x rising from 0 to 1
  std::vector<double> slope;  // at each knot (set by prepare())
  void prepare();
  double operator()(double u) const;
};

// `monotone`: the knot values rise (or fall, at random) from -1 to 1 (or 1 to -1).
SmoothFunction draw_smooth_function(bool monotone, ThirdRandom& random);

// Into and out of a draw's parameters, under `prefix` (prefix_n, prefix_x0, prefix_y0, ...).
void put_smooth_function(const SmoothFunction& f, const std::string& prefix, Params& params);
SmoothFunction get_smooth_function(const Params& params, const std::string& prefix);

// `value` mapped onto [0, 1] over [lo, hi] (hi > lo).
inline double unit_position(double value, double lo, double hi) { return (value - lo) / (hi - lo); }

}  // namespace flange::third_reality
