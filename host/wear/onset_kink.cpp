// SPDX-License-Identifier: MIT
#include "onset_kink.h"

#include <algorithm>
#include <cmath>

namespace flange::host {

double onset_kink_t(const WearSeries& series, const WearLineFit& from_onset, double widening) {
  if (!from_onset.drift_onset_day || series.day.empty() || from_onset.dof <= 0 ||
      from_onset.rss <= 0.0) {
    return 0.0;
  }
  const auto degree = static_cast<int>(from_onset.drift_coefficients.size());
  const WearLineFit smooth = fit_wear_line(series, series.day.front(), degree);
  const double variance = from_onset.rss / from_onset.dof * widening * widening;
  return std::sqrt(std::max(0.0, (smooth.rss - from_onset.rss) / variance));
}

}  // namespace flange::host
