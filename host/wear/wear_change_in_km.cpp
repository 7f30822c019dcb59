// SPDX-License-Identifier: MIT
#include "wear_change_in_km.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>
#include <vector>

namespace flange::host {
namespace {

// `series` with the km since run `onset` and its square as two more regressors.
WearSeries with_change_in_km(WearSeries series, std::size_t onset) {
  const std::size_t n = series.km.size();
  std::vector<double> since(n, 0.0), square(n, 0.0);
  for (std::size_t k = onset; k < n; ++k) {
    since[k] = (series.km[k] - series.km[onset]) / 1000.0;
    square[k] = since[k] * since[k];
  }
  series.shared.push_back(std::move(since));
  series.shared.push_back(std::move(square));
  return series;
}

}  // namespace

WearSeries with_flange_bends(WearSeries series, const std::set<std::size_t>& flange_starts) {
  std::vector<std::size_t> starts{0};
  for (const std::size_t start : flange_starts) {
    if (start > 0 && start < series.km.size()) starts.push_back(start);
  }
  for (std::size_t f = 0; f < starts.size(); ++f) {
    const std::size_t end = f + 1 < starts.size() ? starts[f + 1] : series.km.size();
    if (end - starts[f] < kMinRunsForBend) continue;
    std::vector<double> bend(series.km.size(), 0.0);
    for (std::size_t k = starts[f]; k < end; ++k) {
      const double since = (series.km[k] - series.km[starts[f]]) / 1000.0;
      bend[k] = since * since;
    }
    series.shared.push_back(std::move(bend));
  }
  return series;
}

double best_change_rss(const WearSeries& series, const std::set<std::size_t>& flange_starts,
                       ChangeIn in, int drift_degree, std::size_t runs_before,
                       std::size_t runs_after) {
  const WearSeries bent = with_flange_bends(series, flange_starts);
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t onset = runs_before; onset + runs_after < series.km.size(); ++onset) {
    try {
      const WearLineFit fit =
          in == ChangeIn::days
              ? fit_wear_line(bent, series.day[onset], drift_degree)
              : fit_wear_line(with_change_in_km(bent, onset), std::nullopt);
      best = std::min(best, fit.rss);
    } catch (const std::invalid_argument&) {
      break;  // too few points for the model
    }
  }
  return best;
}

}  // namespace flange::host
