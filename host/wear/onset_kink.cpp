// SPDX-License-Identifier: MIT
#include "onset_kink.h"

#include <limits>
#include <stdexcept>

namespace flange::host {

double onset_kink(const WearSeries& series, const WearLineFit& from_onset) {
  if (!from_onset.drift_onset_day || series.day.empty()) return 0.0;
  constexpr double kSharp = std::numeric_limits<double>::infinity();
  if (from_onset.rss <= 0.0) return kSharp;
  if (*from_onset.drift_onset_day - series.day.front() < kLeastDaysBeforeAKink) return kSharp;
  const auto degree = static_cast<int>(from_onset.drift_coefficients.size()) + 1;
  try {
    return fit_wear_line(series, series.day.front(), degree).rss / from_onset.rss;
  } catch (const std::invalid_argument&) {
    return kSharp;  // too few runs for the smooth bend: nothing to tell the onset from
  }
}

}  // namespace flange::host
