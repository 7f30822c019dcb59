// SPDX-License-Identifier: MIT
// Polynomials in z^-1: products of root factors, roots, and evaluation on the unit circle.
#pragma once

#include <complex>
#include <vector>

namespace flange::coeffs {

using Complex = std::complex<double>;

// Coefficients c[0] + c[1] x + ... of prod_i (x - root_i), highest power first as numpy.poly
// returns them: c[0] = 1. Complex roots must come in conjugate pairs; the imaginary part of the
// result is then rounding noise and is dropped.
std::vector<double> poly_from_roots(const std::vector<Complex>& roots);

// Roots of c[0] x^n + c[1] x^(n-1) + ... + c[n] (highest power first); c[0] != 0.
// Degree 1 and 2 in closed form, higher degrees as companion-matrix eigenvalues.
std::vector<Complex> polynomial_roots(const std::vector<double>& coefficients);

// Value of sum_k c[k] z^-k at z = e^{j omega}; omega in rad/sample.
Complex eval_z_inverse(const std::vector<double>& coefficients, double omega);

}  // namespace flange::coeffs
