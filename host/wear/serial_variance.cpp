// SPDX-License-Identifier: MIT
#include "serial_variance.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace flange::host {

int cosine_terms(Eigen::Index points) {
  const auto nu = static_cast<int>(std::lround(0.4 * std::pow(static_cast<double>(points), 2.0 / 3.0)));
  return std::clamp(nu, 2, std::max(2, static_cast<int>(points) - 1));
}

SerialCovariance serial_covariance(const Eigen::MatrixXd& x, const Eigen::VectorXd& residuals,
                                   const Eigen::MatrixXd& xtx_inverse) {
  const Eigen::Index n = x.rows(), p = x.cols();
  const Eigen::MatrixXd scores = x.array().colwise() * residuals.array();  // z_k = x_k e_k
  const int nu = cosine_terms(n);
  Eigen::MatrixXd omega = Eigen::MatrixXd::Zero(p, p);
  for (int j = 1; j <= nu; ++j) {
    Eigen::VectorXd weights(n);
    for (Eigen::Index k = 0; k < n; ++k) {
      weights(k) = std::sqrt(2.0 / static_cast<double>(n)) *
                   std::cos(std::numbers::pi * j * (static_cast<double>(k) + 0.5) /
                            static_cast<double>(n));
    }
    const Eigen::VectorXd projection = scores.transpose() * weights;  // L_j
    omega += projection * projection.transpose();
  }
  omega /= static_cast<double>(nu);
  // Omega is the variance of sum_k z_k / sqrt(n); the sum's is n Omega.
  SerialCovariance result;
  result.covariance = xtx_inverse * (static_cast<double>(n) * omega) * xtx_inverse;
  result.dof = nu;
  return result;
}

}  // namespace flange::host
