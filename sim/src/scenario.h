// SPDX-License-Identifier: MIT
// A scenario produces the physical truth, sample by sample, at t = n / fs for n = 0, 1, ...
// It streams: nothing of the run is held beyond what its own dynamics need.
#pragma once

#include <cstdint>

#include "chain_sample.h"

namespace flange::sim {

class Scenario {
 public:
  virtual ~Scenario() = default;
  // Samples in the record, fixed at construction.
  virtual std::int64_t sample_count() const = 0;
  // The truth at the next sampling instant; call at most sample_count() times.
  virtual TrueState next() = 0;
};

// Samples at t = n / fs covering [0, duration]: floor(duration * fs) + 1. Requires
// fs_hz > 0 and duration_s >= 0.
std::int64_t sample_count_for(double fs_hz, double duration_s);

}  // namespace flange::sim
