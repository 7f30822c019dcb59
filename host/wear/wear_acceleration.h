// SPDX-License-Identifier: MIT
// Wear that speeds up (or slows) as the flange thins, pooled over the fleet's wheels:
//   dw/dkm = r exp(b (w - w_now)) (1 + gamma (t - t_mean))
// with one acceleration b per mm of wear for the whole estimate (a flange's steel and profile, not
// the wheel, set how its wear changes as it thins; one wheel's history spans about 1 mm and holds
// no useful b of its own) and one calendar trend gamma per day (the season, the fleet's duties:
// every wheel of the fleet shares it). gamma is there because in any one history it is confounded
// with b: a rate that rises over the months (a spring) makes the later, thinner flange look as if
// it wore faster for its thinness, and a reprofiled wheel's new flange look as if it wore slower.
// The reprofiled wheels (the same wheel at two wear levels) and the wheels' differing rates
// (b bends a fast wheel's line more, gamma every wheel's alike per km run) tell them apart.
//
// With u = w - w_now (w_now the current flange's fitted wear at the last run),
// z = (1 - exp(-b u)) / b grows by r (1 + gamma (t - t_mean)) per km on every flange the wheel
// ran (a reprofiling restarts u, not the rate at w_now), and to first order z = u - b u^2 / 2, so
//   y_k = a_seg + r (km_k - km_0) + b q_k + gamma p_k,
//   q_k = (yhat_k - yhat_now)^2 / 2,  p_k = rbar sum_{j<k} (t_j - t_mean) (km_{j+1} - km_j)
// (yhat and rbar the straight line's fitted clearance and rate, free of the runs' noise; t_mean
// the history's km-weighted mean day, so r is the rate at the history's mean season, as the
// straight line's is). A wheel's evidence is the straight line's residuals e and q, p less what
// the line explains (Frisch-Waugh: q_perp, p_perp), each weighted by 1 / (s^2 inflation), its
// run-to-run scatter widened for errors correlated in time as its rate's, s^2 its residuals'
// about the fleet's bend (remade from the pooled b and gamma kAccelerationReweightings times). The
// fleet's (b, gamma) solve the pooled 2 x 2 normal equations; their covariance is the larger (for
// b) of a sandwich clustered by locomotive (wheels on one locomotive share their routes and days;
// locomotives - 1 degrees of freedom) and the weights' own inverse (at the Welch-Satterthwaite
// degrees of freedom of the wheels' variances, (sum w)^2 / sum (w^2 / dof), at most
// kMaxModeratedDof).
//
// The forecast's date always uses them, b weighed by how well the fleet knows it
// (acceleration_in_dates): given them, the line refitted to y - b q - gamma p has the same
// design, so its parameters are the straight line's less b and gamma times q's and p's own fits
// (clearance now c - b g_c - gamma h_c, rate r - b g_r - gamma h_r; limit_forecast.h). The
// calendar trend is not carried forward as a line: the months to a limit span seasons the history
// has not seen, so the rate ahead is the history's mean season's moved by the season's cycle
// through gamma (season_to_come.h), and how far the season to come may stand from that is in the
// date's interval. A wheel with a drift fitted out neither gives evidence nor takes the fleet's b
// (fleet_wear.cpp): its drift terms in days take up a bend of any cause.
#pragma once

#include <string>
#include <vector>

#include "wear_line_fit.h"

namespace flange::host {

// The level at which `flange wear` reports the fleet's b as differing from 0 (FleetAcceleration::
// significant). The dates no longer wait for it: a b of 0.02-0.06 per mm at 4 degrees of freedom
// fails it on 8 of the second reality's 30 development fleets, whose wear does speed up (0.06),
// and there the straight line's dates came early (healthy wheels' warning dates 86 % at 95 %;
// docs/fleet.md, step 6); acceleration_in_dates weighs b instead.
inline constexpr double kAccelerationTestLevel = 0.95;
// The fleet's terms (b and gamma): a wheel's residual variance is taken over its line's degrees
// of freedom less these.
inline constexpr int kAccelerationTerms = 2;
// Times the wheels' weights are remade from their residuals about the fleet's bend: on a fleet
// that bends, the straight line's residuals hold the bend (0.4 mm on a flange reprofiled from
// 4.5 mm at b = 0.04 per mm, several times a run's scatter), which would weigh most the wheels
// that show it most; the weights settle within a few passes.
inline constexpr int kAccelerationReweightings = 3;

// One wheel's evidence about b and gamma, from its straight line (fit_wear_line of the same
// series).
struct AccelerationEvidence {
  double qq = 0.0, qp = 0.0, pp = 0.0;    // q_perp . q_perp, q_perp . p_perp, p_perp . p_perp
  double qe = 0.0, pe = 0.0;              // q_perp . e, p_perp . e
  double rss = 0.0;                       // the straight line's residual sum of squares (mm^2)
  int dof = 0;                            // and its degrees of freedom
  double clearance_gradient = 0.0;        // g_c: q's fit at the last run (mm^2)
  double rate_gradient = 0.0;             // g_r: q's fitted slope (mm^2 per km)
  double clearance_trend_gradient = 0.0;  // h_c: p's fit at the last run (mm day)
  double rate_trend_gradient = 0.0;       // h_r: p's fitted slope (mm day per km)
};

AccelerationEvidence acceleration_evidence(const WearSeries& series, const WearLineFit& fit,
                                           int drift_degree);

struct AccelerationSample {
  std::string locomotive;
  AccelerationEvidence evidence;
  double inflation = 1.0;  // the wheel's rate variance over its least-squares one
  int dof = 1;             // of that variance (the rate's Student t)
};

struct FleetAcceleration {
  double estimate = 0.0;                              // b per mm of wear
  double trend = 0.0;                                 // gamma per day
  double se = 0.0, trend_se = 0.0, covariance = 0.0;  // of (b, gamma)
  int dof = 0;                                        // of se (0: not estimated)
  bool significant = false;  // |b| / se beyond Student t at kAccelerationTestLevel
};

// The b the dates use: the multiple c b of the estimate with the least mean square error,
// c = b^2 / (b^2 + se^2), at the estimate (b^3 / (b^2 + se^2)). A well-known b is used as it is
// (0.06 +- 0.0015: c = 0.9994); one within its own se of 0 counts for little, so a fleet that
// wears linearly keeps nearly the straight line's dates instead of taking its noise (on 400
// linear wheels, b = 0.0024 +- 0.013, the plan's share reaching the limit first at risk 0.3,
// 120 of 400 due, was 84 with b as estimated, 99 weighed: reprofiling_plan_test.cpp). Its
// uncertainty stays se in the interval.
double acceleration_in_dates(const FleetAcceleration& fleet);

// Wheels with no leverage or no residual scatter carry no weight; fewer than two locomotives
// with weight, or terms the fleet cannot tell apart, give no estimate.
FleetAcceleration pool_acceleration(const std::vector<AccelerationSample>& samples);

}  // namespace flange::host
