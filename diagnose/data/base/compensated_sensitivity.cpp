// SPDX-License-Identifier: MIT
#include "compensated_sensitivity.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <vector>

namespace flange::diagnose {
namespace {

// What is left of unit column k once the columns `others` are fitted to it, in the columns' Gram
// matrix scaled to unit diagonal: G_kk - g' G_oo^+ g.
double left_of(const Eigen::MatrixXd& unit, Eigen::Index k,
               const std::vector<Eigen::Index>& others) {
  double left = unit(k, k);
  if (others.empty()) return left;
  const auto o = static_cast<Eigen::Index>(others.size());
  Eigen::MatrixXd g_oo(o, o);
  Eigen::VectorXd g_ok(o);
  for (Eigen::Index a = 0; a < o; ++a) {
    g_ok(a) = unit(others[a], k);
    for (Eigen::Index b = 0; b < o; ++b) g_oo(a, b) = unit(others[a], others[b]);
  }
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver(g_oo);
  solver.setThreshold(1e-9);
  return left - g_ok.dot(solver.solve(g_ok));
}

}  // namespace

Eigen::VectorXd compensated_sensitivity(const Eigen::MatrixXd& gram, Eigen::Index rows) {
  const Eigen::Index m = gram.cols();
  const double n = std::max<double>(1.0, static_cast<double>(rows));
  // Scaled to unit diagonal, so that the rank decisions do not depend on the values' units (a
  // gain per degree beside a reference temperature in degrees).
  const Eigen::VectorXd scale = gram.diagonal().cwiseMax(0.0).cwiseSqrt();
  Eigen::MatrixXd unit = gram;
  std::vector<Eigen::Index> live;
  for (Eigen::Index k = 0; k < m; ++k) {
    if (scale(k) > 0.0) live.push_back(k);
  }
  for (Eigen::Index a : live) {
    for (Eigen::Index b : live) unit(a, b) = gram(a, b) / (scale(a) * scale(b));
  }
  Eigen::VectorXd out = Eigen::VectorXd::Zero(m);
  for (Eigen::Index k : live) {
    std::vector<Eigen::Index> others;
    std::copy_if(live.begin(), live.end(), std::back_inserter(others),
                 [k](Eigen::Index j) { return j != k; });
    out(k) = scale(k) * std::sqrt(std::max(0.0, left_of(unit, k, others)) / n);
  }
  return out;
}

double combination_sensitivity(const Eigen::MatrixXd& gram, Eigen::Index rows,
                               const Eigen::VectorXd& gradient) {
  const Eigen::Index m = gram.cols();
  const double n = std::max<double>(1.0, static_cast<double>(rows));
  // Scaled to unit diagonal, as above; a value nothing moves may not carry the combination.
  Eigen::VectorXd scale = gram.diagonal().cwiseMax(0.0).cwiseSqrt();
  for (Eigen::Index k = 0; k < m; ++k) {
    if (scale(k) > 0.0) continue;
    if (gradient(k) != 0.0) return 0.0;
    scale(k) = 1.0;
  }
  const Eigen::MatrixXd unit = scale.cwiseInverse().asDiagonal() * gram *
                               scale.cwiseInverse().asDiagonal();
  const Eigen::VectorXd g = gradient.cwiseQuotient(scale);
  Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver(unit);
  solver.setThreshold(1e-9);
  const Eigen::VectorXd x = solver.solve(g);
  if ((unit * x - g).norm() > 1e-6 * g.norm()) return 0.0;  // g outside the data's directions
  const double q = g.dot(x);
  return q > 0.0 ? 1.0 / std::sqrt(n * q) : 0.0;
}

}  // namespace flange::diagnose
