// SPDX-License-Identifier: MIT
#include "scenario.h"

#include <cmath>

namespace flange::sim {

std::int64_t sample_count_for(double fs_hz, double duration_s) {
  // The small allowance keeps t = duration when duration * fs is an integer up to rounding.
  return static_cast<std::int64_t>(std::floor(duration_s * fs_hz * (1.0 + 1e-12))) + 1;
}

}  // namespace flange::sim
