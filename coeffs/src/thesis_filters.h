// SPDX-License-Identifier: MIT
// The two filters of the thesis as `flange design` command lines: the checked-in coefficient
// sets (coeffs/regenerate.sh) and `flange demo` are made from these.
#pragma once

#include <string>
#include <vector>

namespace flange::coeffs {

struct ThesisFilter {
  std::string set_name;             // folder under coeffs/
  std::vector<std::string> design;  // arguments after `flange`
  bool expect_rejected;             // the thesis's structure that quantisation breaks
};

// Measurement filter (section 4.3.1, eq. 4.15): fs = 6 Hz, 5th order, fc = 0.5742 Hz.
// Vehicle-dynamics filter (section 4.4.2, eq. 4.20): fs = 100 Hz, 7th order, fc = 0.259 Hz.
const std::vector<ThesisFilter>& thesis_filters();

// A transfer function b(z^-1) / a(z^-1) as the thesis prints it.
struct PrintedTransferFunction {
  std::string equation;  // e.g. "eq. 4.20"
  std::vector<double> b, a;
};

// Eq. 4.20 as printed: the vehicle-dynamics filter's 7th-order direct form, 4 significant digits
// (docs/thesis_filters.md: three of its poles lie outside the unit circle).
const PrintedTransferFunction& thesis_eq_4_20_printed();

}  // namespace flange::coeffs
