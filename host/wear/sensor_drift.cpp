// SPDX-License-Identifier: MIT
#include "sensor_drift.h"

#include <cmath>
#include <stdexcept>

namespace flange::host {
namespace {

// The onset whose drift fits the difference best (smallest residual), with its fit.
std::optional<std::pair<double, WearLineFit>> best_onset(const WearSeries& difference) {
  std::optional<std::pair<double, WearLineFit>> best;
  const std::size_t n = difference.day.size();
  for (std::size_t k = 0; k + kMinRunsAfterOnset < n; ++k) {
    try {
      WearLineFit fit = fit_wear_line(difference, difference.day[k]);
      if (!best || fit.rss < best->second.rss) best.emplace(difference.day[k], std::move(fit));
    } catch (const std::invalid_argument&) {
      return best;  // too few points for the drift model
    }
  }
  return best;
}

double drift_t(const WearSeries& series, double onset_day) {
  const WearLineFit fit = fit_wear_line(series, onset_day);
  return fit.drift_se > 0.0 ? *fit.drift_mm_per_day / fit.drift_se : 0.0;
}

}  // namespace

std::optional<DriftFinding> find_sensor_drift(const WearSeries& difference,
                                              const WearSeries& left_series,
                                              const WearSeries& right_series) {
  const auto best = best_onset(difference);
  if (!best) return std::nullopt;
  const auto& [onset, fit] = *best;
  const double g = *fit.drift_mm_per_day;
  const double t = fit.drift_se > 0.0 ? g / fit.drift_se : 0.0;
  const double size = std::abs(g) * (difference.day.back() - onset);
  if (std::abs(t) < kDriftTStatistic || size < kMinDriftMm) return std::nullopt;
  DriftFinding finding;
  finding.left = std::abs(drift_t(left_series, onset)) > std::abs(drift_t(right_series, onset));
  finding.onset_day = onset;
  finding.difference_t = t;
  finding.size_mm = size;
  const WearLineFit own = fit_wear_line(finding.left ? left_series : right_series, onset);
  finding.rate_mm_per_day = *own.drift_mm_per_day;
  return finding;
}

}  // namespace flange::host
