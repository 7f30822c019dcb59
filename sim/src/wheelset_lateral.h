// SPDX-License-Identifier: MIT
// Reduced-order lateral dynamics of one wheelset relative to its bogie frame, which carries the
// sensor: the wheelset mass on its axle-box leads (spring and damper), with the axle-box bump
// stop beyond the allowed lateral play. Parameters are the thesis's Appendix A values.
//
//   m x'' + c x' + k x + f_stop(x) = F_curve(t) - m a_irr(t)
//
// x: wheelset displacement relative to the bogie towards the sensor (m); k = leads * c_Lead_y,
// c = leads * d_Lead_y with d_Lead_y = 2 B_Lead sqrt(m c_Lead_y); F_curve: the curve's
// quasi-static lateral load through the leads (supported mass times unbalanced acceleration);
// a_irr: the track irregularity's lateral acceleration, entering as a base motion (the frame
// follows the alignment, the wheelset's inertia lags on its leads).
#pragma once

namespace flange::sim {

struct WheelsetLateralParameters {
  double wheelset_mass_kg = 3105.0;            // m_WSet (Tables 0-4 to 0-6)
  double lead_stiffness_n_per_m = 2.5e6;       // c_Lead_y, one axle-box lead (Table 0-4)
  double lead_damping_ratio = 0.05;            // B_Lead (Table 0-4)
  int leads = 2;                               // both axle-box leads carry the wheelset
  double bump_stop_gap_m = 0.015;              // axlebox_gap, allowed lateral play (Table 0-5)
  double bump_stop_stiffness_n_per_m = 1.0e7;  // c_gap (Table 0-5)
  // Mass whose lateral load in a curve passes through this wheelset's leads: the body and the
  // two frames shared over six wheelsets, (m_body + 2 m_Frame) / 6 (Tables 0-2, 0-3).
  double supported_mass_kg = (81000.0 + 2.0 * 11000.0) / 6.0;
};

// d_Lead_y of one lead, 2 B sqrt(m k): 8810.5 N s/m for the thesis values (Table 0-4).
double lead_damping_ns_per_m(const WheelsetLateralParameters& p);

// Undamped natural frequency sqrt(leads k / m) / 2 pi: 4.52 Hz on one lead, 6.39 Hz on two.
double lateral_natural_frequency_hz(const WheelsetLateralParameters& p);

class WheelsetLateral {
 public:
  explicit WheelsetLateral(const WheelsetLateralParameters& p);

  // Advances by dt (> 0) with one classical Runge-Kutta step. `force_n(t)` is the external
  // lateral force on the wheelset, F_curve(t) - m a_irr(t), evaluated at t, t + dt/2, t + dt.
  template <typename Force>
  void step(double t_s, double dt_s, const Force& force_n) {
    const double f0 = force_n(t_s);
    const double f_mid = force_n(t_s + 0.5 * dt_s);
    const double f1 = force_n(t_s + dt_s);
    const double k1x = velocity_;
    const double k1v = acceleration(displacement_, velocity_, f0);
    const double k2x = velocity_ + 0.5 * dt_s * k1v;
    const double k2v =
        acceleration(displacement_ + 0.5 * dt_s * k1x, velocity_ + 0.5 * dt_s * k1v, f_mid);
    const double k3x = velocity_ + 0.5 * dt_s * k2v;
    const double k3v =
        acceleration(displacement_ + 0.5 * dt_s * k2x, velocity_ + 0.5 * dt_s * k2v, f_mid);
    const double k4x = velocity_ + dt_s * k3v;
    const double k4v = acceleration(displacement_ + dt_s * k3x, velocity_ + dt_s * k3v, f1);
    displacement_ += dt_s / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
    velocity_ += dt_s / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
  }

  double displacement_m() const { return displacement_; }
  double velocity_mps() const { return velocity_; }
  double mass_kg() const { return mass_kg_; }
  double supported_mass_kg() const { return supported_mass_kg_; }

 private:
  double acceleration(double x, double v, double force_n) const;

  double mass_kg_;
  double stiffness_n_per_m_;
  double damping_ns_per_m_;
  double gap_m_;
  double stop_stiffness_n_per_m_;
  double supported_mass_kg_;
  double displacement_ = 0.0;
  double velocity_ = 0.0;
};

}  // namespace flange::sim
