// SPDX-License-Identifier: MIT
// Reprofilings found in the data: the depot turns both wheels of an axle on the lathe together,
// so the axle's mean static clearance jumps back (the flange is thick again) between two runs.
// Wear only opens the clearance, and the thesis bounds the wear between two measurements by h
// (eq. 3.38, ThresholdConfig::max_step_mm): a fall larger than h is not wear or noise.
#pragma once

#include <cstddef>
#include <vector>

namespace flange::host {

// Indices k (1 .. size - 1) of the runs whose axle mean (left + right) / 2 fell by more than
// max_step_mm since run k - 1: the first run on a reprofiled flange. `left` and `right` hold the
// two wheels' clearances run by run (the same runs).
std::vector<std::size_t> find_reprofilings(const std::vector<double>& left,
                                           const std::vector<double>& right, double max_step_mm);

}  // namespace flange::host
