// SPDX-License-Identifier: MIT
#include "shared_grid.h"

#include <cmath>
#include <vector>

namespace flange::diagnose {

bool same_grid(const AdcGrid& a, const AdcGrid& b) {
  const double codes_apart = (b.lowest_v - a.lowest_v) / a.lsb_v;
  return std::abs(a.lsb_v - b.lsb_v) <= 1e-3 * a.lsb_v &&
         std::abs(codes_apart - std::round(codes_apart)) < 0.05;
}

std::optional<AdcGrid> shared_grid(const RecordingSeries& calibration,
                                   const RecordingSeries& heldout) {
  const auto cal_grid = estimate_adc_grid(calibration.voltage_v);
  const auto ho_grid = estimate_adc_grid(heldout.voltage_v);
  if (!cal_grid || !ho_grid || !same_grid(*cal_grid, *ho_grid)) return std::nullopt;
  std::vector<double> both = calibration.voltage_v;
  both.insert(both.end(), heldout.voltage_v.begin(), heldout.voltage_v.end());
  return estimate_adc_grid(both);
}

}  // namespace flange::diagnose
