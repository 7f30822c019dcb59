// SPDX-License-Identifier: MIT
// A first-order lag discretised with the input held at its last sampled value over each step
// (zero-order hold), exact for that held input: y += (1 - exp(-dt / tau)) (x_prev - y). It
// starts in equilibrium with its first input. (The twin holds the input linear between samples;
// this is deliberately another discretisation.)
#pragma once

#include <cmath>

namespace flange::alt_reality {

class FirstOrderLag {
 public:
  explicit FirstOrderLag(double tau_s) : tau_s_(tau_s) {}

  double step(double t_s, double input) {
    if (!started_) {
      output_ = input;
      started_ = true;
    } else {
      output_ += (1.0 - std::exp(-(t_s - last_t_s_) / tau_s_)) * (last_input_ - output_);
    }
    last_t_s_ = t_s;
    last_input_ = input;
    return output_;
  }

 private:
  double tau_s_;
  bool started_ = false;
  double output_ = 0.0, last_t_s_ = 0.0, last_input_ = 0.0;
};

}  // namespace flange::alt_reality
