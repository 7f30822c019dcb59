// SPDX-License-Identifier: MIT
#include "ridge_solve.h"

#include <algorithm>

namespace flange::diagnose::free_shapes {

Eigen::VectorXd ridge_solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& y) {
  return ridge_solve_normal(a.transpose() * a, a.transpose() * y);
}

Eigen::VectorXd ridge_solve_normal(Eigen::MatrixXd normal, const Eigen::VectorXd& aty) {
  const double largest = normal.diagonal().maxCoeff();
  for (Eigen::Index j = 0; j < normal.rows(); ++j) {
    normal(j, j) += kRidge * normal(j, j) + 1e-12 * std::max(largest, 1e-300);
  }
  return normal.ldlt().solve(aty);
}

Eigen::MatrixXd matrix(std::size_t rows, std::size_t cols) {
  return Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(rows), static_cast<Eigen::Index>(cols));
}

std::vector<double> as_vector(const Eigen::VectorXd& v) {
  return std::vector<double>(v.data(), v.data() + v.size());
}

}  // namespace flange::diagnose::free_shapes
