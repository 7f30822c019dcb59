// SPDX-License-Identifier: MIT
#include "measurement_chain.h"

#include <optional>

#include "float_design.h"

namespace flange::diagnose {

std::vector<double> measurement_filter(const std::vector<double>& x, double fs_hz) {
  const coeffs::FloatDesign design =
      coeffs::design_butterworth(5, 0.574 / 6.0 * fs_hz, fs_hz, std::nullopt);
  const std::vector<double>& b = design.b;
  const std::vector<double>& a = design.a;
  std::vector<double> y(x.size(), 0.0);
  // Start from rest at the first input (a DC-settled state), so the start-up is not a gap.
  for (std::size_t n = 0; n < x.size(); ++n) {
    double acc = 0.0;
    for (std::size_t k = 0; k < b.size(); ++k) acc += b[k] * (n >= k ? x[n - k] : x.front());
    for (std::size_t k = 1; k < a.size(); ++k) acc -= a[k] * (n >= k ? y[n - k] : x.front());
    y[n] = acc;
  }
  return y;
}

std::vector<double> clearance_of(const sim::PolynomialSensorModel& model,
                                 const std::vector<double>& v, const std::vector<double>& t) {
  std::vector<double> d(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) d[i] = model.clearance_mm(v[i], t[i]);
  return d;
}

}  // namespace flange::diagnose
