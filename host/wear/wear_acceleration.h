// SPDX-License-Identifier: MIT
// Wear that speeds up (or slows) as the flange thins, pooled over the fleet's wheels:
//   dw/dkm = r(w) = r_ref exp(b (w - w_ref))
// with one acceleration b per mm of wear for the whole estimate (a flange's steel and profile, not
// the wheel, set how its wear changes as it thins; one wheel's history spans about 1 mm and holds
// no useful b of its own). With u = w - w_now (w_now the current flange's fitted wear at the last
// run), z = (1 - exp(-b u)) / b grows by r_now per km on every flange the wheel ran (each
// reprofiling restarts u, not the rate at w_now), and to first order z = u - b u^2 / 2, so
//   y_k = a_seg + r_now (km_k - km_0) + b q_k,  q_k = (yhat_k - yhat_now)^2 / 2
// (yhat the straight line's fitted clearance, free of the run's noise). A wheel's b is the
// straight line's residuals regressed on q's part that the line does not explain (Frisch-Waugh):
// b_i = sum(q_perp e) / sum(q_perp^2), variance s^2 inflation / sum(q_perp^2) (the wheel's
// run-to-run scatter widened for errors correlated in time, as its rate's). The lathe's step
// gives a reprofiled wheel most of its weight: its old flange wore at a rate exp(b 4.5 mm) from
// its new one's. The fleet's b is the precision-weighted mean; its standard error the larger of
// the weights' own and the scatter of the locomotives' weighted sums (wheels on one locomotive
// share their routes and days), with locomotives - 1 degrees of freedom.
//
// The forecast uses b only when it differs from 0 at kAccelerationTestLevel: a fleet whose wear
// is a straight line in km keeps the straight line's forecast unchanged. Given b, the line
// refitted to y - b q has the same design, so its parameters are the straight line's less b
// times q's own fit: the clearance now c - b g_c and the rate now r - b g_r (limit_forecast.h).
#pragma once

#include <string>
#include <vector>

#include "wear_line_fit.h"

namespace flange::host {

// The level at which the fleet's b must differ from 0 before the forecast uses it: below it the
// straight line's forecast stands (a fleet wearing linearly gets the dates it had without b).
inline constexpr double kAccelerationTestLevel = 0.95;

// One wheel's evidence about b, from its straight line (fit_wear_line of the same series).
struct AccelerationEvidence {
  double projection = 0.0;         // sum q_perp e (mm^3)
  double leverage = 0.0;           // sum q_perp^2 (mm^4)
  double residual_variance = 0.0;  // s^2 of the straight line (mm^2)
  double clearance_gradient = 0.0;  // g_c: q's fit at the last run (mm^2)
  double rate_gradient = 0.0;       // g_r: q's fitted slope (mm^2 per km)
};

AccelerationEvidence acceleration_evidence(const WearSeries& series, const WearLineFit& fit,
                                           int drift_degree);

struct AccelerationSample {
  std::string locomotive;
  AccelerationEvidence evidence;
  double inflation = 1.0;  // the wheel's rate variance over its least-squares one
};

struct FleetAcceleration {
  double estimate = 0.0;  // b per mm, as pooled
  double se = 0.0;
  int dof = 0;             // locomotives - 1 (0: not estimated)
  bool significant = false;  // |b| / se beyond Student t at kAccelerationTestLevel
  // What the forecast uses: the estimate and its se when significant, else 0 and 0.
  double used() const { return significant ? estimate : 0.0; }
  double used_se() const { return significant ? se : 0.0; }
};

// Wheels with no leverage or no residual scatter carry no weight; fewer than two locomotives
// with weight give no estimate.
FleetAcceleration pool_acceleration(const std::vector<AccelerationSample>& samples);

}  // namespace flange::host
