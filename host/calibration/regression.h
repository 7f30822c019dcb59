// SPDX-License-Identifier: MIT
// The regression stage: clearance from sensor voltage and temperature,
// d = sum a_ij V^i T^j (thesis eq. 3.11), fitted by Householder QR on scaled variables, with
// the order chosen by the thesis's r >= 0.975 rule and blocked k-fold cross-validation.
#pragma once

#include <Eigen/Dense>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace flange::host {

// Calibration points: one row per measurement.
struct CalibrationData {
  std::vector<double> voltage_v;
  std::vector<double> temp_c;
  std::vector<double> clearance_mm;
};

// The monomials of order p: V^i T^j with i + j <= p and j <= max(1, p - 1). Order 2 is the
// thesis's eq. 3.10/3.14 form {1, V, T, V^2, V T}. Terms are listed lowest order first, so the
// terms of order p are a prefix of those of order p + 1.
std::vector<std::pair<int, int>> regression_terms(int order);
inline constexpr int kMinRegressionOrder = 1;
inline constexpr int kMaxRegressionOrder = 6;

// Affine map of V and T onto about [-1, 1] before the monomials are formed: keeps the
// least-squares problem well conditioned (raw V^4 T^3 would span 12 decades).
struct VariableScaling {
  double v_center = 5.0, v_half = 5.0;
  double t_center = 50.0, t_half = 50.0;
};

struct FitStatistics {
  double r = 0.0;            // sqrt(1 - SSE/SST), thesis eq. 3.9
  double adjusted_r2 = 0.0;  // 1 - (1 - r^2)(N - 1)/(N - p)
  double rmse_mm = 0.0;
  double mae_mm = 0.0;
  double heldout_mae_mm = 0.0;  // k-fold cross-validation, interleaved blocks of 64 rows
  double heldout_rmse_mm = 0.0;
};

class RegressionModel {
 public:
  RegressionModel() = default;
  RegressionModel(int order, VariableScaling scaling, Eigen::VectorXd scaled_coefficients);

  double clearance_mm(double voltage_v, double temp_c) const;
  int order() const { return order_; }
  const VariableScaling& scaling() const { return scaling_; }
  const Eigen::VectorXd& scaled_coefficients() const { return scaled_; }
  // The same polynomial in raw V (volts) and T (deg C): a_ij for every (i, j) of the order.
  std::vector<double> raw_coefficients() const;
  // The fitted polynomial as text: "1.16 + 0.3672 V - 0.0036 T + ..." (raw coefficients).
  std::string equation() const;

 private:
  int order_ = 0;
  VariableScaling scaling_;
  Eigen::VectorXd scaled_;                  // one per regression_terms(order_)
  std::vector<std::pair<int, int>> terms_;  // regression_terms(order_), kept for speed
};

struct OrderCandidate {
  int order = 0;
  std::size_t terms = 0;
  FitStatistics stats;
};

struct RegressionFit {
  RegressionModel model;
  FitStatistics stats;
  std::vector<OrderCandidate> candidates;  // every order tried, lowest first
  std::string selection;                   // why this order, in one sentence
};

struct RegressionOptions {
  int max_order = 4;                  // [1, 6]
  int folds = 5;                      // [2, 20]; interleaved blocks of 64 consecutive rows
  double min_r = 0.975;               // the thesis's acceptance threshold, (0, 1)
  // The held-out MAE gain that justifies one more order: below a tenth of a micrometre is noise.
  // No relative bar: a misfit well under the noise hardly moves the MAE, yet a wear rate (a
  // change of clearance over months, the noise averaged away) carries its slope error whole, and
  // the cross-validation already charges an order for what it over-fits.
  double min_heldout_gain_mm = 1e-4;
};

// Fits and selects the order. Throws InputError (degenerate data: too few points, a constant
// column, rank deficiency) with a message naming the problem and what would fix it.
RegressionFit fit_regression(const CalibrationData& data, const RegressionOptions& options);

}  // namespace flange::host
