// SPDX-License-Identifier: MIT
#include "polynomial.h"

#include <Eigen/Eigenvalues>
#include <cmath>
#include <cstddef>

namespace flange::coeffs {

std::vector<double> poly_from_roots(const std::vector<Complex>& roots) {
  // Successive convolution with (1, -root), in the roots' order, as numpy.poly does: the same
  // order of operations keeps the result within rounding of scipy's.
  std::vector<Complex> acc{Complex(1.0, 0.0)};
  for (const Complex& root : roots) {
    std::vector<Complex> next(acc.size() + 1, Complex(0.0, 0.0));
    for (std::size_t i = 0; i < acc.size(); ++i) {
      next[i] += acc[i];
      next[i + 1] -= acc[i] * root;
    }
    acc = std::move(next);
  }
  std::vector<double> real(acc.size());
  for (std::size_t i = 0; i < acc.size(); ++i) real[i] = acc[i].real();
  return real;
}

std::vector<Complex> polynomial_roots(const std::vector<double>& coefficients) {
  std::size_t first = 0;
  while (first < coefficients.size() && coefficients[first] == 0.0) ++first;
  const std::size_t degree = coefficients.size() - first - 1;
  if (first >= coefficients.size() || degree == 0) return {};
  const double lead = coefficients[first];
  if (degree == 1) return {Complex(-coefficients[first + 1] / lead, 0.0)};
  if (degree == 2) {
    const double p = coefficients[first + 1] / lead;
    const double q = coefficients[first + 2] / lead;
    const double disc = p * p / 4.0 - q;
    if (disc >= 0.0) {
      // The root of larger magnitude first, the other from Vieta: no cancellation.
      const double big = -p / 2.0 - std::copysign(std::sqrt(disc), p);
      if (big == 0.0) return {Complex(0.0, 0.0), Complex(0.0, 0.0)};
      return {Complex(big, 0.0), Complex(q / big, 0.0)};
    }
    const double im = std::sqrt(-disc);
    return {Complex(-p / 2.0, im), Complex(-p / 2.0, -im)};
  }
  const auto n = static_cast<Eigen::Index>(degree);
  Eigen::MatrixXd companion = Eigen::MatrixXd::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    companion(0, j) = -coefficients[first + 1 + static_cast<std::size_t>(j)] / lead;
  }
  for (Eigen::Index i = 1; i < n; ++i) companion(i, i - 1) = 1.0;
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(companion, /*computeEigenvectors=*/false);
  std::vector<Complex> roots(degree);
  for (Eigen::Index i = 0; i < n; ++i) roots[static_cast<std::size_t>(i)] = solver.eigenvalues()(i);
  return roots;
}

Complex eval_z_inverse(const std::vector<double>& coefficients, double omega) {
  // Horner in w = e^{-j omega}.
  const Complex w = std::polar(1.0, -omega);
  Complex acc(0.0, 0.0);
  for (std::size_t i = coefficients.size(); i-- > 0;) acc = acc * w + coefficients[i];
  return acc;
}

}  // namespace flange::coeffs
