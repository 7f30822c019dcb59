// SPDX-License-Identifier: MIT
// The covariance of least-squares coefficients when the errors are correlated from run to run.
// A wheel's clearance carries, besides each run's own scatter, what moves slowly: the season's
// temperature leftovers (the calibration's regression is exact at no temperature), a sensor's
// creep, the reference a run is centred on. Those errors are correlated over weeks, and the
// ordinary (X^T X)^-1 s^2 treats them as independent, so its intervals are too narrow.
//
// The long-run variance of the scores z_k = x_k e_k is estimated by equal-weighted cosines
// (EWC): Omega = (1/nu) sum_{j=1..nu} L_j L_j^T, L_j = sqrt(2/n) sum_k z_k cos(pi j (k - 1/2)/n),
// the sandwich (X^T X)^-1 Omega (X^T X)^-1, and a coefficient over its standard error is
// Student t with nu degrees of freedom, so no critical value comes from a table (Lazarus, Lewis,
// Stock and Watson, "HAR inference: recommendations for practice", 2018; nu = 0.4 n^(2/3) is
// their rule for the number of cosines). The cosines keep only the lowest frequencies of the
// scores, the ones the slow errors live in.
#pragma once

#include <Eigen/Dense>

namespace flange::host {

struct SerialCovariance {
  Eigen::MatrixXd covariance;  // of the coefficients, in the columns' order
  int dof = 0;                 // nu: Student t's degrees of freedom for any one coefficient
};

// nu for n points in time order: round(0.4 n^(2/3)), at least 2, at most n - 1.
int cosine_terms(Eigen::Index points);

// x: n x p design in time order; residuals: n; xtx_inverse: (X^T X)^-1 (p x p). n >= 3.
SerialCovariance serial_covariance(const Eigen::MatrixXd& x, const Eigen::VectorXd& residuals,
                                   const Eigen::MatrixXd& xtx_inverse);

}  // namespace flange::host
