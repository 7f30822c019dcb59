// SPDX-License-Identifier: MIT
#include "negative_rate.h"

#include <limits>
#include <stdexcept>

namespace flange::host {
namespace {

// Runs either side of a step or an onset: a level or a slope needs two.
constexpr std::size_t kRunsEachSide = 2;

double best_rss(const WearSeries& series, bool step) {
  double best = std::numeric_limits<double>::infinity();
  const std::size_t n = series.y.size();
  for (std::size_t k = kRunsEachSide; k + kRunsEachSide <= n; ++k) {
    try {
      if (step) {
        if (series.segment[k] != series.segment[k - 1]) continue;  // already a new flange
        WearSeries stepped = series;
        for (std::size_t j = k; j < n; ++j) ++stepped.segment[j];
        best = std::min(best, fit_wear_line(stepped, std::nullopt).rss);
      } else {
        best = std::min(best, fit_wear_line(series, series.day[k], 1).rss);
      }
    } catch (const std::invalid_argument&) {
      continue;  // too few points for this split
    }
  }
  return best;
}

}  // namespace

NegativeRateCause negative_rate_cause(const WearSeries& series) {
  return best_rss(series, true) < best_rss(series, false) ? NegativeRateCause::kMissedReprofiling
                                                          : NegativeRateCause::kSensorFault;
}

const char* status_text(NegativeRateCause cause) {
  return cause == NegativeRateCause::kMissedReprofiling ? "missed reprofiling" : "sensor fault";
}

}  // namespace flange::host
