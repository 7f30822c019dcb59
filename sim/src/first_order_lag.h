// SPDX-License-Identifier: MIT
// A first-order lag of a temperature stepped sample by sample, exact for an input that is linear
// between samples (a first-order hold), so that a ramp lags by exactly tau whatever the sample
// rate; the record starts in equilibrium. What the thermal effects lag the ambient by.
#pragma once

#include <cmath>

namespace flange::sim {

class FirstOrderLag {
 public:
  explicit FirstOrderLag(double tau_s) : tau_s_(tau_s) {}  // tau_s > 0

  // The lagged value at `t_s` (called with increasing t_s) for the input `x` there.
  double step(double t_s, double x) {
    if (!started_) {
      lagged_ = x;
      started_ = true;
    } else {
      const double dt = t_s - last_t_s_;
      const double decay = std::exp(-dt / tau_s_);
      const double slope = dt > 0.0 ? (x - last_x_) / dt : 0.0;
      lagged_ = x - tau_s_ * slope + decay * (lagged_ - last_x_ + tau_s_ * slope);
    }
    last_t_s_ = t_s;
    last_x_ = x;
    return lagged_;
  }

 private:
  double tau_s_;
  bool started_ = false;
  double lagged_ = 0.0;
  double last_t_s_ = 0.0;
  double last_x_ = 0.0;
};

}  // namespace flange::sim
