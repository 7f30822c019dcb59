// SPDX-License-Identifier: MIT
#include "lag_kernel.h"

#include <cmath>

namespace flange::third_reality {

LagKernel draw_lag_kernel(int paths, double tau_lo_s, double tau_hi_s, double dead_hi_s,
                          ThirdRandom& random) {
  LagKernel kernel;
  double total = 0.0;
  for (int p = 0; p < paths; ++p) {
    LagPath path;
    path.weight = random.uniform(0.2, 1.0);
    path.tau_s = random.log_uniform(tau_lo_s, tau_hi_s);
    path.dead_s = random.chance(1.0 / 3.0) ? random.uniform(0.0, dead_hi_s) : 0.0;
    total += path.weight;
    kernel.paths.push_back(path);
  }
  for (LagPath& path : kernel.paths) path.weight /= total;
  return kernel;
}

std::vector<double> apply_lag_kernel(const LagKernel& kernel,
                                     const std::function<double(double)>& x,
                                     const std::vector<double>& instants_s) {
  std::vector<double> out(instants_s.size(), 0.0);
  if (instants_s.empty()) return out;
  for (const LagPath& path : kernel.paths) {
    double previous_x = x(instants_s[0] - path.dead_s), y = previous_x;
    out[0] += path.weight * y;
    for (std::size_t k = 1; k < instants_s.size(); ++k) {
      const double h = instants_s[k] - instants_s[k - 1];
      const double xk = x(instants_s[k] - path.dead_s);
      // dy/dt = (x - y) / tau with x linear over the step: y = x - s tau + (y0 - x0 + s tau)
      // e^-h/tau.
      const double slope = (xk - previous_x) / h, decay = std::exp(-h / path.tau_s);
      y = xk - slope * path.tau_s + (y - previous_x + slope * path.tau_s) * decay;
      previous_x = xk;
      out[k] += path.weight * y;
    }
  }
  return out;
}

void put_lag_kernel(const LagKernel& kernel, const std::string& prefix, Params& params) {
  params[prefix + "_paths"] = static_cast<double>(kernel.paths.size());
  for (std::size_t p = 0; p < kernel.paths.size(); ++p) {
    const std::string key = prefix + std::to_string(p);
    params[key + "_weight"] = kernel.paths[p].weight;
    params[key + "_tau_s"] = kernel.paths[p].tau_s;
    params[key + "_dead_s"] = kernel.paths[p].dead_s;
  }
}

LagKernel get_lag_kernel(const Params& params, const std::string& prefix) {
  LagKernel kernel;
  const auto n = static_cast<std::size_t>(params.at(prefix + "_paths"));
  for (std::size_t p = 0; p < n; ++p) {
    const std::string key = prefix + std::to_string(p);
    kernel.paths.push_back(
        {params.at(key + "_weight"), params.at(key + "_tau_s"), params.at(key + "_dead_s")});
  }
  return kernel;
}

}  // namespace flange::third_reality
