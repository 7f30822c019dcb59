// SPDX-License-Identifier: MIT
#include "wear_line_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>

namespace flange::host {

WearLineFit fit_wear_line(const WearSeries& series, std::optional<double> drift_onset_day) {
  const auto n = static_cast<Eigen::Index>(series.y.size());
  const int segments =
      series.segment.empty() ? 1 : *std::max_element(series.segment.begin(), series.segment.end()) + 1;
  const Eigen::Index params = segments + 1 + (drift_onset_day ? 1 : 0);
  if (n <= params) throw std::invalid_argument("fit_wear_line: too few points for the model");
  WearLineFit fit;
  fit.km0 = series.km.front();
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, params);
  Eigen::VectorXd y(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    x(k, series.segment[i]) = 1.0;
    x(k, segments) = series.km[i] - fit.km0;
    if (drift_onset_day) x(k, segments + 1) = std::max(0.0, series.day[i] - *drift_onset_day);
    y(k) = series.y[i];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(x);
  const Eigen::VectorXd beta = qr.solve(y);
  fit.rss = (y - x * beta).squaredNorm();
  fit.dof = static_cast<int>(n - params);
  fit.residual_sd = std::sqrt(fit.rss / fit.dof);
  // (X^T X)^-1 from the same QR, never from the normal equations: P R^-1 R^-T P^T.
  const Eigen::MatrixXd r_upper =
      qr.matrixR().topLeftCorner(params, params).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd r_inverse = r_upper.triangularView<Eigen::Upper>().solve(
      Eigen::MatrixXd::Identity(params, params));
  const Eigen::MatrixXd xtx_inv =
      qr.colsPermutation() * (r_inverse * r_inverse.transpose()) * qr.colsPermutation().transpose();
  const Eigen::MatrixXd cov = xtx_inv * (fit.residual_sd * fit.residual_sd);
  for (int s = 0; s < segments; ++s) fit.intercepts_mm.push_back(beta(s));
  fit.rate_mm_per_km = beta(segments);
  fit.rate_se = std::sqrt(cov(segments, segments));
  if (drift_onset_day) {
    fit.drift_mm_per_day = beta(segments + 1);
    fit.drift_se = std::sqrt(cov(segments + 1, segments + 1));
  }
  fit.covariance.assign(static_cast<std::size_t>(params), std::vector<double>());
  for (Eigen::Index r = 0; r < params; ++r) {
    for (Eigen::Index c = 0; c < params; ++c) {
      fit.covariance[static_cast<std::size_t>(r)].push_back(cov(r, c));
    }
  }
  return fit;
}

double wear_line_at(const WearLineFit& fit, int segment, double km) {
  return fit.intercepts_mm.at(static_cast<std::size_t>(segment)) +
         fit.rate_mm_per_km * (km - fit.km0);
}

double t95(int dof) {
  const boost::math::students_t distribution(std::max(1, dof));
  return boost::math::quantile(boost::math::complement(distribution, 0.025));
}

}  // namespace flange::host
