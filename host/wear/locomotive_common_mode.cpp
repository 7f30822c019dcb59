// SPDX-License-Identifier: MIT
#include "locomotive_common_mode.h"

#include <algorithm>
#include <stdexcept>

#include "robust_location.h"

namespace flange::host {
namespace {

// Each axle's residuals from its own straight wear law (the null the drift search fits, so the
// shared part is all of what that search would see, a shared wander included), gathered by run
// id; an axle with too few runs for the law gives none.
void add_residuals(const WearSeries& series, const std::vector<std::int64_t>& run_id,
                   std::map<std::int64_t, std::vector<double>>& by_run) {
  try {
    const WearLineFit fit = fit_wear_line(series, std::nullopt);
    for (std::size_t k = 0; k < run_id.size(); ++k) by_run[run_id[k]].push_back(fit.residuals[k]);
  } catch (const std::invalid_argument&) {
    // too few runs: this axle takes no part
  }
}

std::map<std::int64_t, double> medians(const std::map<std::int64_t, std::vector<double>>& by_run) {
  std::map<std::int64_t, double> shared;
  for (const auto& [run, values] : by_run) {
    if (values.size() >= kMinAxlesForCommonMode) shared[run] = median(values);
  }
  return shared;
}

}  // namespace

CommonMode locomotive_common_mode(const std::vector<AxleSeries>& axles) {
  std::map<std::int64_t, std::vector<double>> sums, differences;
  for (const AxleSeries& axle : axles) {
    add_residuals(axle.sum, axle.run_id, sums);
    add_residuals(axle.difference, axle.run_id, differences);
  }
  return {medians(sums), medians(differences)};
}

WearSeries without_common_mode(WearSeries series, const std::vector<std::int64_t>& run_id,
                               const std::map<std::int64_t, double>& shared) {
  for (std::size_t k = 0; k < run_id.size(); ++k) {
    const auto found = shared.find(run_id[k]);
    if (found != shared.end()) series.y[k] -= found->second;
  }
  return series;
}

WearSeries with_shared_shapes(WearSeries series, const std::vector<std::int64_t>& run_id,
                              const CommonMode& common) {
  for (const auto* shared : {&common.sum_mm, &common.difference_mm}) {
    std::vector<double> shape;
    for (const std::int64_t run : run_id) {
      const auto found = shared->find(run);
      shape.push_back(found != shared->end() ? found->second : 0.0);
    }
    // None of this axle's runs has it (a locomotive of fewer than kMinAxlesForCommonMode
    // axles): a column of zeros would leave the fit without a covariance.
    if (std::all_of(shape.begin(), shape.end(), [](double v) { return v == 0.0; })) continue;
    series.shared.push_back(std::move(shape));
  }
  return series;
}

}  // namespace flange::host
