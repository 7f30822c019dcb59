// SPDX-License-Identifier: MIT
// The wear model of one series, fitted by least squares (Eigen's column-pivoting QR):
//   y_k = a_seg(k) + r (km_k - km_0) [+ g max(0, day_k - onset)]
// one intercept per segment (a reprofiling starts a new one: the flange is new again), one rate
// per km for the whole series (the wheel wears at its own rate whatever its flange's age), and
// optionally a drift per day from an onset: a sensor's offset creeping with time, not distance.
#pragma once

#include <optional>
#include <vector>

namespace flange::host {

struct WearSeries {
  std::vector<double> km;   // odometer at each point
  std::vector<double> day;  // days since 1970-01-01
  std::vector<double> y;    // the fitted quantity (mm)
  std::vector<int> segment;  // 0, 0, ..., 1, 1, ...: which flange each point saw
};

struct WearLineFit {
  std::vector<double> intercepts_mm;  // a_seg: y at km_0 (the series' first odometer reading)
  double km0 = 0.0;
  double rate_mm_per_km = 0.0;
  double rate_se = 0.0;  // its standard error
  std::optional<double> drift_mm_per_day;  // g, with an onset
  double drift_se = 0.0;
  double rss = 0.0;          // residual sum of squares
  int dof = 0;               // points minus parameters
  double residual_sd = 0.0;  // sqrt(rss / dof)
  // (X^T X)^-1 scaled by the residual variance, in the parameter order
  // [intercepts..., rate, drift]: for the forecast's interval.
  std::vector<std::vector<double>> covariance;
};

// At least one more point than parameters. Throws std::invalid_argument otherwise.
WearLineFit fit_wear_line(const WearSeries& series, std::optional<double> drift_onset_day);

// y of the fitted line (without the drift) at odometer km on segment seg.
double wear_line_at(const WearLineFit& fit, int segment, double km);

// Half-width multiplier of a two-sided 95 % interval with `dof` degrees of freedom (Student t).
double t95(int dof);

}  // namespace flange::host
