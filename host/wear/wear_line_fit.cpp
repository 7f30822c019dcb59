// SPDX-License-Identifier: MIT
#include "wear_line_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <stdexcept>

namespace flange::host {
namespace {

std::vector<std::vector<double>> rows_of(const Eigen::MatrixXd& matrix) {
  std::vector<std::vector<double>> rows(static_cast<std::size_t>(matrix.rows()));
  for (Eigen::Index r = 0; r < matrix.rows(); ++r) {
    for (Eigen::Index c = 0; c < matrix.cols(); ++c) {
      rows[static_cast<std::size_t>(r)].push_back(matrix(r, c));
    }
  }
  return rows;
}

}  // namespace

WearLineFit fit_wear_line(const WearSeries& series, std::optional<double> drift_onset_day,
                          int drift_degree) {
  const auto n = static_cast<Eigen::Index>(series.y.size());
  const int segments = series.segment.empty()
                           ? 1
                           : *std::max_element(series.segment.begin(), series.segment.end()) + 1;
  const Eigen::Index first_shared = segments + 1;
  const Eigen::Index first_drift = first_shared + static_cast<Eigen::Index>(series.shared.size());
  const Eigen::Index params = first_drift + (drift_onset_day ? drift_degree : 0);
  if (n <= params) throw std::invalid_argument("fit_wear_line: too few points for the model");
  WearLineFit fit;
  fit.km0 = series.km.front();
  Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, params);
  Eigen::VectorXd y(n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const auto i = static_cast<std::size_t>(k);
    x(k, series.segment[i]) = 1.0;
    x(k, segments) = series.km[i] - fit.km0;
    for (std::size_t j = 0; j < series.shared.size(); ++j) {
      x(k, first_shared + static_cast<Eigen::Index>(j)) = series.shared[j][i];
    }
    const double since_onset =
        drift_onset_day ? std::max(0.0, series.day[i] - *drift_onset_day) : 0.0;
    const double scale = series.drift_scale.empty() ? 1.0 : series.drift_scale[i];
    for (int power = 1; drift_onset_day && power <= drift_degree; ++power) {
      x(k, first_drift + power - 1) = scale * std::pow(since_onset, power);
    }
    y(k) = series.y[i];
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(x);
  const Eigen::VectorXd beta = qr.solve(y);
  fit.full_rank = qr.rank() == params;
  const Eigen::VectorXd residuals = y - x * beta;
  fit.residuals.assign(residuals.data(), residuals.data() + n);
  fit.rss = residuals.squaredNorm();
  fit.dof = static_cast<int>(n - params);
  fit.residual_sd = std::sqrt(fit.rss / fit.dof);
  // (X^T X)^-1 from the same QR, never from the normal equations: P R^-1 R^-T P^T.
  const Eigen::MatrixXd r_upper =
      qr.matrixR().topLeftCorner(params, params).triangularView<Eigen::Upper>();
  const Eigen::MatrixXd r_inverse =
      r_upper.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(params, params));
  const Eigen::MatrixXd xtx_inv =
      qr.colsPermutation() * (r_inverse * r_inverse.transpose()) * qr.colsPermutation().transpose();
  const Eigen::MatrixXd cov = xtx_inv * (fit.residual_sd * fit.residual_sd);
  for (int s = 0; s < segments; ++s) fit.intercepts_mm.push_back(beta(s));
  fit.rate_mm_per_km = beta(segments);
  fit.rate_se = std::sqrt(cov(segments, segments));
  for (std::size_t j = 0; j < series.shared.size(); ++j) {
    fit.shared_coefficients.push_back(beta(first_shared + static_cast<Eigen::Index>(j)));
  }
  fit.drift_onset_day = drift_onset_day;
  fit.drift_index = static_cast<std::size_t>(first_drift);
  for (int power = 1; drift_onset_day && power <= drift_degree; ++power) {
    fit.drift_coefficients.push_back(beta(first_drift + power - 1));
  }
  fit.covariance = rows_of(cov);
  return fit;
}

double wear_line_at(const WearLineFit& fit, int segment, double km) {
  return fit.intercepts_mm.at(static_cast<std::size_t>(segment)) +
         fit.rate_mm_per_km * (km - fit.km0);
}

DriftValue drift_at(const WearLineFit& fit, double day, double scale) {
  if (!fit.drift_onset_day || day <= *fit.drift_onset_day) return {};
  const double since = day - *fit.drift_onset_day;
  const std::size_t first = fit.drift_index;
  std::vector<double> gradient;
  DriftValue value;
  for (std::size_t p = 0; p < fit.drift_coefficients.size(); ++p) {
    gradient.push_back(scale * std::pow(since, static_cast<double>(p + 1)));
    value.mm += fit.drift_coefficients[p] * gradient.back();
  }
  double variance = 0.0;
  for (std::size_t a = 0; a < gradient.size(); ++a) {
    for (std::size_t b = 0; b < gradient.size(); ++b) {
      variance += gradient[a] * gradient[b] * fit.covariance[first + a][first + b];
    }
  }
  value.se = std::sqrt(std::max(0.0, variance));
  return value;
}

double t95(int dof) { return t_quantile(0.95, dof); }

double t_quantile(double level, int dof) {
  const boost::math::students_t distribution(std::max(1, dof));
  return boost::math::quantile(boost::math::complement(distribution, (1.0 - level) / 2.0));
}

double t_one_sided(double p, int dof) {
  return boost::math::quantile(boost::math::students_t(std::max(1, dof)), p);
}

}  // namespace flange::host
