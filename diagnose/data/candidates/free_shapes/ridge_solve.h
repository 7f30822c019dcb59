// SPDX-License-Identifier: MIT
// The one least-squares solver of the free shapes: a light relative ridge, so that two nearly
// equal columns cannot carry huge opposite values that cancel on one part and not on the other.
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <vector>

namespace flange::diagnose::free_shapes {

// Relative ridge: each column's own sum of squares times this is added to the normal equations.
// Small enough to leave a well-posed fit as it is (a thousandth of a column's weight), large
// enough that two nearly equal columns (a 60 s and a 240 s lag on a slow heating) cannot carry
// huge opposite values that cancel on one session and not on the other.
inline constexpr double kRidge = 1e-3;

// Least squares of `y` on the columns of `a` with the relative ridge; a column with no weight at
// all (a hat over a temperature never visited) gets 0.
Eigen::VectorXd ridge_solve(const Eigen::MatrixXd& a, const Eigen::VectorXd& y);
// The same from the normal equations: a'a and a'y.
Eigen::VectorXd ridge_solve_normal(Eigen::MatrixXd normal, const Eigen::VectorXd& aty);

// A rows x cols matrix of zeros.
Eigen::MatrixXd matrix(std::size_t rows, std::size_t cols);

std::vector<double> as_vector(const Eigen::VectorXd& v);

}  // namespace flange::diagnose::free_shapes
