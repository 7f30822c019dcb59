// SPDX-License-Identifier: MIT
#include "wear_acceleration.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace flange::host {

AccelerationEvidence acceleration_evidence(const WearSeries& series, const WearLineFit& fit,
                                           int drift_degree) {
  const int last_segment = series.segment.back();
  const double now = wear_line_at(fit, last_segment, series.km.back());
  WearSeries bend = series;
  for (std::size_t k = 0; k < series.y.size(); ++k) {
    const double u = wear_line_at(fit, series.segment[k], series.km[k]) - now;
    bend.y[k] = u * u / 2.0;
  }
  const WearLineFit bend_fit = fit_wear_line(bend, fit.drift_onset_day, drift_degree);
  AccelerationEvidence evidence;
  for (std::size_t k = 0; k < series.y.size(); ++k) {
    evidence.projection += bend_fit.residuals[k] * fit.residuals[k];
    evidence.leverage += bend_fit.residuals[k] * bend_fit.residuals[k];
  }
  evidence.residual_variance = fit.residual_sd * fit.residual_sd;
  evidence.clearance_gradient = wear_line_at(bend_fit, last_segment, series.km.back());
  evidence.rate_gradient = bend_fit.rate_mm_per_km;
  return evidence;
}

FleetAcceleration pool_acceleration(const std::vector<AccelerationSample>& samples) {
  // Per locomotive: sum of weights w_i = leverage / variance and of w_i b_i = projection / variance.
  std::map<std::string, std::pair<double, double>> by_locomotive;
  double weight = 0.0, weighted = 0.0;
  for (const AccelerationSample& sample : samples) {
    const double variance = sample.evidence.residual_variance * sample.inflation;
    if (!(variance > 0.0) || !(sample.evidence.leverage > 0.0)) continue;
    auto& [w, wb] = by_locomotive[sample.locomotive];
    w += sample.evidence.leverage / variance;
    wb += sample.evidence.projection / variance;
    weight += sample.evidence.leverage / variance;
    weighted += sample.evidence.projection / variance;
  }
  FleetAcceleration fleet;
  const auto locomotives = static_cast<double>(by_locomotive.size());
  if (by_locomotive.size() < 2 || !(weight > 0.0)) return fleet;
  fleet.estimate = weighted / weight;
  double scatter = 0.0;  // sum over locomotives of (sum_i w_i (b_i - b))^2
  for (const auto& [locomotive, sums] : by_locomotive) {
    const double deviation = sums.second - sums.first * fleet.estimate;
    scatter += deviation * deviation;
  }
  const double clustered = locomotives / (locomotives - 1.0) * scatter / (weight * weight);
  fleet.se = std::sqrt(std::max(1.0 / weight, clustered));
  fleet.dof = static_cast<int>(by_locomotive.size()) - 1;
  fleet.significant =
      std::abs(fleet.estimate) > t_quantile(kAccelerationTestLevel, fleet.dof) * fleet.se;
  return fleet;
}

}  // namespace flange::host
