// SPDX-License-Identifier: MIT
#include "new_flange_rates.h"

#include <utility>

namespace flange::host {

WearSeries with_new_flange_rates(WearSeries series, const std::set<std::size_t>& first_runs) {
  for (const std::size_t first : first_runs) {
    if (first == 0 || first >= series.km.size()) continue;
    std::vector<double> since(series.km.size(), 0.0);
    for (std::size_t k = first; k < series.km.size(); ++k) {
      since[k] = series.km[k] - series.km[first];
    }
    // A flange with no km run since its first run has no rate to fit (a column of zeros would
    // leave the fit without a covariance).
    if (since.back() == 0.0) continue;
    series.shared.push_back(std::move(since));
  }
  return series;
}

}  // namespace flange::host
