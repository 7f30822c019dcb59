// SPDX-License-Identifier: MIT
// The sensor twin's nominal model: a calibration polynomial d = sum a_ij V^i T^j (thesis
// eq. 3.11) used backwards, giving the voltage an ideal sensor outputs for a clearance d at
// temperature T. Any calibration's coefficients can stand in for the thesis's eq. 3.14.
#pragma once

#include <Eigen/Core>
#include <array>

namespace flange::sim {

// Which output rail, if any, the sensor voltage was clipped to.
enum class RailClip { kNone, kLow, kHigh };

struct VoltageSolution {
  double volts = 0.0;
  RailClip clip = RailClip::kNone;
};

class PolynomialSensorModel {
 public:
  // Highest power of V or T a model may use: 10^15 on the 0-10 V range is already beyond what
  // double precision can fit meaningfully.
  static constexpr int kMaxOrder = 15;

  // a(i, j) multiplies V^i T^j (V in volts, T in deg C, d in mm). Requires finite entries, at
  // most kMaxOrder + 1 rows and columns, and a non-zero V term; v_min_v < v_max_v (the sensor's
  // output range, 0-10 V for the thesis sensor). Throws BadArgument otherwise.
  explicit PolynomialSensorModel(const Eigen::MatrixXd& a, double v_min_v = 0.0,
                                 double v_max_v = 10.0);

  // Thesis eq. 3.14 (fitted to bench data up to 98 deg C):
  // d = 1.16 + 0.3672 V - 0.0036 T + 0.05812 V^2 + 0.0006618 V T.
  static PolynomialSensorModel thesis_eq_3_14();

  // Clearance in mm the calibration assigns to `volts` at `temp_c`.
  double clearance_mm(double volts, double temp_c) const;

  // The voltage in [v_min, v_max] at which clearance_mm(V, temp_c) == clearance_mm: the root of
  // a 1-D polynomial in V, found with Brent's method (to 1e-12 V). When no root lies in the
  // range the voltage is clipped to the rail whose clearance is nearer and `clip` says which.
  // Non-monotone models take the first root above v_min.
  VoltageSolution voltage_for(double clearance_mm, double temp_c) const;

  // The same root found by Newton's method from `guess_v` (a nearby sample's voltage), for
  // callers that invert millions of samples close to a known one (the diagnosis's replays).
  // Falls back to voltage_for whenever Newton leaves the range or does not settle within a few
  // steps, so it agrees with voltage_for to within voltage_for's own 1e-12 V tolerance.
  VoltageSolution voltage_near(double clearance_mm, double temp_c, double guess_v) const;

  const Eigen::MatrixXd& coefficients() const { return a_; }
  double v_min_v() const { return v_min_v_; }
  double v_max_v() const { return v_max_v_; }
  // True when dd/dV keeps one sign over the range for -40 to 150 deg C (checked on a grid); the
  // inversion then brackets the whole range at once instead of scanning for a sign change.
  bool monotone_in_voltage() const { return monotone_in_voltage_; }

 private:
  using VoltagePolynomial = std::array<double, kMaxOrder + 1>;
  // Coefficients c_i(T) = sum_j a_ij T^j of the polynomial in V at a fixed temperature.
  VoltagePolynomial at_temperature(double temp_c) const;
  double evaluate(const VoltagePolynomial& c, double volts) const;

  Eigen::MatrixXd a_;
  double v_min_v_;
  double v_max_v_;
  bool monotone_in_voltage_ = false;
};

}  // namespace flange::sim
