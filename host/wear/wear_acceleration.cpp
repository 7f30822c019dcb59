// SPDX-License-Identifier: MIT
#include "wear_acceleration.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>

#include "moderated_spread.h"

namespace flange::host {

AccelerationEvidence acceleration_evidence(const WearSeries& series, const WearLineFit& fit,
                                           int drift_degree) {
  const std::size_t n = series.y.size();
  const int last_segment = series.segment.back();
  const double now = wear_line_at(fit, last_segment, series.km.back());
  double km_days = 0.0, km_run = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    km_days += series.day[k] * (series.km[k + 1] - series.km[k]);
    km_run += series.km[k + 1] - series.km[k];
  }
  const double mean_day = km_run > 0.0 ? km_days / km_run : series.day.back();
  WearSeries bend = series, trend = series;
  trend.y[0] = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const double u = wear_line_at(fit, series.segment[k], series.km[k]) - now;
    bend.y[k] = u * u / 2.0;
    if (k > 0) {
      trend.y[k] = trend.y[k - 1] + fit.rate_mm_per_km * (series.day[k - 1] - mean_day) *
                                        (series.km[k] - series.km[k - 1]);
    }
  }
  const WearLineFit bend_fit = fit_wear_line(bend, fit.drift_onset_day, drift_degree);
  const WearLineFit trend_fit = fit_wear_line(trend, fit.drift_onset_day, drift_degree);
  AccelerationEvidence evidence;
  for (std::size_t k = 0; k < n; ++k) {
    const double q = bend_fit.residuals[k], p = trend_fit.residuals[k], e = fit.residuals[k];
    evidence.qq += q * q;
    evidence.qp += q * p;
    evidence.pp += p * p;
    evidence.qe += q * e;
    evidence.pe += p * e;
  }
  evidence.rss = fit.rss;
  evidence.dof = fit.dof;
  evidence.clearance_gradient = wear_line_at(bend_fit, last_segment, series.km.back());
  evidence.rate_gradient = bend_fit.rate_mm_per_km;
  evidence.clearance_trend_gradient = wear_line_at(trend_fit, last_segment, series.km.back());
  evidence.rate_trend_gradient = trend_fit.rate_mm_per_km;
  return evidence;
}

namespace {

// The weighted normal equations A theta = c, per locomotive and in all, with each wheel's
// variance its residuals' about the fleet's bend `theta` (zero: the straight line's).
struct Sums {
  Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
};

struct Pooled {
  std::map<std::string, Sums> by_locomotive;
  Sums all;
  double weight = 0.0, weight_spread = 0.0;  // sum w_i and sum w_i^2 / dof_i, w_i = q_perp^2 / v_i
};

Pooled pooled_sums(const std::vector<AccelerationSample>& samples, const Eigen::Vector2d& theta) {
  Pooled pooled;
  for (const AccelerationSample& sample : samples) {
    const AccelerationEvidence& e = sample.evidence;
    if (!(e.qq > 0.0) || !(e.pp > 0.0) || e.dof <= kAccelerationTerms) continue;
    Sums wheel;
    wheel.a << e.qq, e.qp, e.qp, e.pp;
    wheel.c << e.qe, e.pe;
    // |e - Q theta|^2 = rss - 2 theta.c + theta' A theta, over the line's dof less the two terms.
    const double rss = e.rss - 2.0 * theta.dot(wheel.c) + theta.dot(wheel.a * theta);
    const double variance = rss / (e.dof - kAccelerationTerms) * sample.inflation;
    if (!(variance > 0.0)) continue;
    pooled.weight += e.qq / variance;
    pooled.weight_spread += e.qq * e.qq / (variance * variance) / std::max(1, sample.dof);
    Sums& locomotive = pooled.by_locomotive[sample.locomotive];
    for (Sums* sums : {&locomotive, &pooled.all}) {
      sums->a += wheel.a / variance;
      sums->c += wheel.c / variance;
    }
  }
  return pooled;
}

}  // namespace

FleetAcceleration pool_acceleration(const std::vector<AccelerationSample>& samples) {
  Eigen::Vector2d theta = Eigen::Vector2d::Zero();
  Pooled pooled;
  for (int pass = 0; pass <= kAccelerationReweightings; ++pass) {
    pooled = pooled_sums(samples, theta);
    const Eigen::FullPivLU<Eigen::Matrix2d> lu(pooled.all.a);
    if (pooled.by_locomotive.size() < 2 || !lu.isInvertible()) return {};
    theta = lu.solve(pooled.all.c);
  }
  const auto& [by_locomotive, all, weight, weight_spread] = pooled;
  FleetAcceleration fleet;
  const Eigen::Matrix2d a_inverse = all.a.inverse();
  // The sandwich: each locomotive's score sum_i (c_i - A_i theta), its outer products summed.
  Eigen::Matrix2d meat = Eigen::Matrix2d::Zero();
  for (const auto& [locomotive, sums] : by_locomotive) {
    const Eigen::Vector2d score = sums.c - sums.a * theta;
    meat += score * score.transpose();
  }
  const auto locomotives = static_cast<double>(by_locomotive.size());
  Eigen::Matrix2d covariance = locomotives / (locomotives - 1.0) * a_inverse * meat * a_inverse;
  // The locomotives' scatter with their few degrees of freedom, or the weights' own with the
  // wheels' (Welch-Satterthwaite over the weights' variances), whichever is the larger.
  fleet.dof = static_cast<int>(by_locomotive.size()) - 1;
  if (covariance(0, 0) < a_inverse(0, 0)) {
    covariance = a_inverse;
    fleet.dof = static_cast<int>(
        std::min<double>(kMaxModeratedDof, std::floor(weight * weight / weight_spread)));
  }
  fleet.estimate = theta(0);
  fleet.trend = theta(1);
  fleet.se = std::sqrt(covariance(0, 0));
  fleet.trend_se = std::sqrt(covariance(1, 1));
  fleet.covariance = covariance(0, 1);
  fleet.significant =
      std::abs(fleet.estimate) > t_quantile(kAccelerationTestLevel, fleet.dof) * fleet.se;
  return fleet;
}

double acceleration_in_dates(const FleetAcceleration& fleet) {
  const double b = fleet.estimate;
  const double square = b * b + fleet.se * fleet.se;
  return square > 0.0 ? b * b * b / square : 0.0;
}

}  // namespace flange::host
