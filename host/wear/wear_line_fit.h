// SPDX-License-Identifier: MIT
// The wear model of one series, fitted by least squares (Eigen's column-pivoting QR):
//   y_k = a_seg(k) + r (km_k - km_0) [+ m_k (g tau_k (+ g2 tau_k^2))],  tau_k = max(0, day_k -
//   onset)
// one intercept per segment (a reprofiling starts a new one: the flange is new again), one rate
// per km for the whole series (the wheel wears at its own rate whatever its flange's age),
// optionally shared shapes s_j with coefficients c_j (WearSeries::shared), and optionally a
// drift from an onset: a sensor's offset creeping with time, not distance, scaled
// at each point by m_k (WearSeries::drift_scale).
#pragma once

#include <optional>
#include <vector>

namespace flange::host {

struct WearSeries {
  std::vector<double> km;    // odometer at each point
  std::vector<double> day;   // days since 1970-01-01
  std::vector<double> y;     // the fitted quantity (mm)
  std::vector<int> segment;  // 0, 0, ..., 1, 1, ...: which flange each point saw
  // Multiplies the drift terms point by point (a drift in volts read through the sensor's
  // slope in mm/V at that point: sensor_sensitivity.h); empty: 1, a drift in mm.
  std::vector<double> drift_scale;
  // Further regressors, each with a coefficient of its own and as long as y (the shapes the
  // locomotive's axles share, at this axle's scale: locomotive_common_mode.h; a new flange's
  // own rate: new_flange_rates.h). Empty: none.
  std::vector<std::vector<double>> shared;
};

struct WearLineFit {
  std::vector<double> intercepts_mm;  // a_seg: y at km_0 (the series' first odometer reading)
  double km0 = 0.0;
  double rate_mm_per_km = 0.0;
  double rate_se = 0.0;  // its standard error
  std::vector<double> shared_coefficients;  // c_j of WearSeries::shared, in its order
  std::optional<double> drift_onset_day;
  std::vector<double> drift_coefficients;  // g, g2: per day and per day^2 (in mm / m_k)
  std::size_t drift_index = 0;             // where they sit among the parameters
  std::vector<double> residuals;           // y minus the fit, point by point
  double rss = 0.0;                        // residual sum of squares
  int dof = 0;                             // points minus parameters
  double residual_sd = 0.0;                // sqrt(rss / dof)
  bool full_rank = true;  // every parameter fixed by the data (a piece or segment without runs: not)
  // (X^T X)^-1 scaled by the residual variance, in the parameter order
  // [intercepts..., rate, shared..., drift]: the run-to-run scatter only (block_jackknife.h widens it for
  // errors correlated from run to run).
  std::vector<std::vector<double>> covariance;
};

// drift_degree 1 or 2 (with an onset). At least one more point than parameters. Throws
// std::invalid_argument otherwise.
WearLineFit fit_wear_line(const WearSeries& series, std::optional<double> drift_onset_day,
                          int drift_degree = 1);

// y of a straight fitted line (without the drift) at odometer km on segment seg.
double wear_line_at(const WearLineFit& fit, int segment, double km);

struct DriftValue {
  double mm = 0.0;  // the fitted drift at a time
  double se = 0.0;  // its standard error
};

// The fitted drift at `day` scaled by `scale` (0 before the onset, or without a drift).
DriftValue drift_at(const WearLineFit& fit, double day, double scale = 1.0);

// Half-width multiplier of a two-sided 95 % interval with `dof` degrees of freedom (Student t).
double t95(int dof);

// The same for a two-sided interval at `level` (0 < level < 1).
double t_quantile(double level, int dof);

// The one-sided Student t quantile at probability `p` with `dof` degrees of freedom (at least 1):
// the value a t variable stays below with probability p.
double t_one_sided(double p, int dof);

}  // namespace flange::host
