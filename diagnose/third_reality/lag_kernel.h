// SPDX-License-Identifier: MIT
// A random lag kernel of one to three paths: each path a dead time followed by a first-order lag,
// the paths weighted to a sum of 1 (a body that warms through a fast and a slow way, a sheath
// that delays before it lags). Applied to a function of time at rising instants, exactly for an
// input that is linear between them, starting settled at the first instant.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "smooth_function.h"
#include "third_random.h"

namespace flange::third_reality {

struct LagPath {
  double weight = 1.0;
  double tau_s = 300.0;  // > 0
  double dead_s = 0.0;   // >= 0
};

struct LagKernel {
  std::vector<LagPath> paths;
};

// `paths` paths (1-3); taus log-uniform in [tau_lo_s, tau_hi_s], dead times in [0, dead_hi_s]
// on a path with probability one in three.
LagKernel draw_lag_kernel(int paths, double tau_lo_s, double tau_hi_s, double dead_hi_s,
                          ThirdRandom& random);

// The kernel's output for input `x` at `instants_s` (rising).
std::vector<double> apply_lag_kernel(const LagKernel& kernel,
                                     const std::function<double(double)>& x,
                                     const std::vector<double>& instants_s);

void put_lag_kernel(const LagKernel& kernel, const std::string& prefix, Params& params);
LagKernel get_lag_kernel(const Params& params, const std::string& prefix);

}  // namespace flange::third_reality
