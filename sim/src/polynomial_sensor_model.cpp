// SPDX-License-Identifier: MIT
#include "polynomial_sensor_model.h"

#include <fmt/format.h>

#include <cmath>

#include "root_find.h"
#include "sim_error.h"

namespace flange::sim {
namespace {

// Root tolerance in volts: far below the 1e-9 mm round-trip the tests ask for (dd/dV <= 3 mm/V).
constexpr double kVoltageTolerance = 1e-12;
// Newton steps tried before voltage_near falls back to Brent: a start within a volt converges
// in three or four on the thesis's quadratic.
constexpr int kNewtonSteps = 8;
// Cells scanned for the first sign change when the model is not monotone in V.
constexpr int kScanCells = 64;

}  // namespace

PolynomialSensorModel::PolynomialSensorModel(const Eigen::MatrixXd& a, double v_min_v,
                                             double v_max_v)
    : a_(a), v_min_v_(v_min_v), v_max_v_(v_max_v) {
  if (a.rows() < 1 || a.cols() < 1 || a.rows() > kMaxOrder + 1 || a.cols() > kMaxOrder + 1) {
    throw BadArgument(fmt::format(
        "nominal model: coefficient matrix is {}x{}; needs 1 to {} rows (powers of V) and "
        "columns (powers of T)",
        a.rows(), a.cols(), kMaxOrder + 1));
  }
  if (!a.allFinite()) throw BadArgument("nominal model: every coefficient must be finite");
  if (a.rows() < 2 || a.bottomRows(a.rows() - 1).cwiseAbs().maxCoeff() == 0.0) {
    throw BadArgument("nominal model: needs a non-zero V term (a_ij with i >= 1) to be inverted");
  }
  if (!std::isfinite(v_min_v) || !std::isfinite(v_max_v) || v_min_v >= v_max_v) {
    throw BadArgument(fmt::format(
        "nominal model: voltage range [{}, {}] V must be finite with min < max", v_min_v, v_max_v));
  }
  // Sign of dd/dV on a grid covering the sensor range and every plausible temperature.
  constexpr int kVoltageSteps = 200;
  bool positive = true;
  bool negative = true;
  for (double temp_c = -40.0; temp_c <= 150.0; temp_c += 5.0) {
    const VoltagePolynomial c = at_temperature(temp_c);
    for (int k = 0; k <= kVoltageSteps; ++k) {
      const double volts = v_min_v + (v_max_v - v_min_v) * k / kVoltageSteps;
      double slope = 0.0;
      for (Eigen::Index i = a_.rows() - 1; i >= 1; --i) {
        slope = slope * volts + static_cast<double>(i) * c[static_cast<std::size_t>(i)];
      }
      positive = positive && slope > 0.0;
      negative = negative && slope < 0.0;
    }
  }
  monotone_in_voltage_ = positive || negative;
}

PolynomialSensorModel PolynomialSensorModel::thesis_eq_3_14() {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(3, 2);
  a(0, 0) = 1.16;
  a(1, 0) = 0.3672;
  a(0, 1) = -0.0036;
  a(2, 0) = 0.05812;
  a(1, 1) = 0.0006618;
  return PolynomialSensorModel(a);
}

PolynomialSensorModel::VoltagePolynomial PolynomialSensorModel::at_temperature(
    double temp_c) const {
  VoltagePolynomial c{};
  for (Eigen::Index i = 0; i < a_.rows(); ++i) {
    double sum = 0.0;
    for (Eigen::Index j = a_.cols() - 1; j >= 0; --j) sum = sum * temp_c + a_(i, j);
    c[static_cast<std::size_t>(i)] = sum;
  }
  return c;
}

double PolynomialSensorModel::evaluate(const VoltagePolynomial& c, double volts) const {
  double sum = 0.0;
  for (Eigen::Index i = a_.rows() - 1; i >= 0; --i) {
    sum = sum * volts + c[static_cast<std::size_t>(i)];
  }
  return sum;
}

double PolynomialSensorModel::clearance_mm(double volts, double temp_c) const {
  return evaluate(at_temperature(temp_c), volts);
}

VoltageSolution PolynomialSensorModel::voltage_for(double clearance_mm, double temp_c) const {
  const VoltagePolynomial c = at_temperature(temp_c);
  const auto residual = [&](double volts) { return evaluate(c, volts) - clearance_mm; };
  const double r_min = residual(v_min_v_);
  const double r_max = residual(v_max_v_);
  if (monotone_in_voltage_) {
    if ((r_min > 0.0) != (r_max > 0.0) || r_min == 0.0 || r_max == 0.0) {
      return {brent_root(residual, v_min_v_, v_max_v_, r_min, r_max, kVoltageTolerance),
              RailClip::kNone};
    }
  } else {
    double lo = v_min_v_;
    double r_lo = r_min;
    for (int cell = 1; cell <= kScanCells; ++cell) {
      const double hi = v_min_v_ + (v_max_v_ - v_min_v_) * cell / kScanCells;
      const double r_hi = residual(hi);
      if ((r_lo > 0.0) != (r_hi > 0.0) || r_lo == 0.0 || r_hi == 0.0) {
        return {brent_root(residual, lo, hi, r_lo, r_hi, kVoltageTolerance), RailClip::kNone};
      }
      lo = hi;
      r_lo = r_hi;
    }
  }
  // No root in range: the sensor sits on the rail whose clearance is nearer to the target.
  if (std::abs(r_min) <= std::abs(r_max)) return {v_min_v_, RailClip::kLow};
  return {v_max_v_, RailClip::kHigh};
}

VoltageSolution PolynomialSensorModel::voltage_near(double clearance_mm, double temp_c,
                                                    double guess_v) const {
  if (!monotone_in_voltage_ || !(guess_v >= v_min_v_ && guess_v <= v_max_v_)) {
    return voltage_for(clearance_mm, temp_c);
  }
  const VoltagePolynomial c = at_temperature(temp_c);
  double volts = guess_v;
  for (int step = 0; step < kNewtonSteps; ++step) {
    double value = 0.0;
    double slope = 0.0;
    for (Eigen::Index i = a_.rows() - 1; i >= 0; --i) {
      slope = slope * volts + value;
      value = value * volts + c[static_cast<std::size_t>(i)];
    }
    if (slope == 0.0) break;
    const double change = (value - clearance_mm) / slope;
    volts -= change;
    if (!(volts >= v_min_v_ && volts <= v_max_v_)) break;  // a rail, or a wild step: Brent decides
    if (std::abs(change) < kVoltageTolerance) return {volts, RailClip::kNone};
  }
  return voltage_for(clearance_mm, temp_c);
}

}  // namespace flange::sim
