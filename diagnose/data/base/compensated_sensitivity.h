// SPDX-License-Identifier: MIT
// How far the data follow one value of a fit when the fit's other values may compensate: the
// local, linear form of a profile over that value.
#pragma once

#include <Eigen/Dense>

namespace flange::diagnose {

// For each column k of `columns` (one row per sample: how the fitted voltage moves per unit of
// value k), the RMS over the rows of what is left of the column once the other columns are
// fitted to it by least squares: a change dv of value k moves the fitted voltage by
// dv times this, beyond anything the other values can take back. 0 for a column the others
// reproduce (or that is 0 everywhere).
// Computed from the columns' Gram matrix `gram` (columns' * columns) and the number of rows.
Eigen::VectorXd compensated_sensitivity(const Eigen::MatrixXd& gram, Eigen::Index rows);

// The same for a combination of the values (a quantity derived from them) whose gradient over the
// values is `gradient`: the least RMS change of the fitted voltage per unit change of the
// combination, the values free to move every other way, 1 / sqrt(g' M^+ g) with M = gram / rows.
// 0 when the combination moves with a direction of the values that moves nothing in the data.
// For the gradient of value k alone it is compensated_sensitivity's k-th entry.
double combination_sensitivity(const Eigen::MatrixXd& gram, Eigen::Index rows,
                               const Eigen::VectorXd& gradient);

}  // namespace flange::diagnose
