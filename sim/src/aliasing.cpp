// SPDX-License-Identifier: MIT
#include "aliasing.h"

#include <cmath>

namespace flange::sim {

double alias_frequency_hz(double frequency_hz, double sample_rate_hz) {
  return std::abs(frequency_hz - sample_rate_hz * std::round(frequency_hz / sample_rate_hz));
}

}  // namespace flange::sim
