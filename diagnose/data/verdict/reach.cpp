// SPDX-License-Identifier: MIT
#include "reach.h"

#include <algorithm>

#include "criteria.h"
#include "series_arithmetic.h"
#include "series_statistics.h"

namespace flange::diagnose {

HeldoutWindow worst_window(const RecordingSeries& heldout, const CalibrationReach& reach,
                           const std::vector<double>& error) {
  const std::vector<std::size_t>& within = reach.heldout_within;
  const std::size_t n = within.size();
  const std::size_t length =
      std::max(n / criteria::kLocalWindows, criteria::kLeastLocalWindowSamples);
  HeldoutWindow worst;
  for (std::size_t begin = 0; begin + length <= n; begin += length) {
    const auto window = std::span(within).subspan(begin, length);
    const double rms = rms_at(error, window);
    if (rms > worst.rms_v) worst = {heldout.t_s[window.front()], heldout.t_s[window.back()], rms};
  }
  return worst;
}

double above_noise_share_taken(double rms_before, double rms_after, double noise) {
  const double before = rms_above_noise(rms_before, noise);
  if (before <= 0.0) return 0.0;
  return 1.0 - rms_above_noise(rms_after, noise) / before;
}

}  // namespace flange::diagnose
