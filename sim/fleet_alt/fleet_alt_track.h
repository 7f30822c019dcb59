// SPDX-License-Identifier: MIT
// The second fleet reality's routes and what they do to a wheelset's lateral position.
//
// A route is a loop of tangents and curves of either hand (each curve entered and left through
// a 50 m linear ramp of curvature), with its own share of curve, share of right-hand curves,
// radii, speed and daily distance, and a lateral alignment of its track (a sum of sines of 8 to
// 70 m wavelength, fixed per route). An axle's lateral shift y (mm, positive to the left: the
// left clearance closes by y, the right one opens by y) at the point s of the route is
//   y = f_axle [ hand 0.35 min(1, 1500 |k|) + hand 1.6 max(0, v^2 |k| - 0.45) ]   (curving,
//       capped at 1.8 mm: the axle box's lateral play)
//     + 0.7 alignment(s)
//     + hunting on tangents: A(v, s) sin(2 pi s / L_k + phase), L_k = 2 pi sqrt(r0 b / conicity),
//       conicity = 0.06 + 0.025 wear (a worn profile hunts at a shorter wavelength),
//       A = 0.4 mm clamp((v - 15) / 8, 0, 1) (0.6 + 0.4 sin(2 pi s / 900 m + phase2))
// with f_axle the axle's steering share (leading axles of a bogie 1.3, middle 0.7, trailing 1).
#pragma once

#include <string>
#include <vector>

#include "fleet_alt_random.h"

namespace flange::fleet_alt {

struct RouteKind {
  std::string name;
  double curve_share = 0.2;       // of the route's length, ramps included
  double right_hand_share = 0.5;  // of its curves
  double radius_low_m = 400.0, radius_high_m = 900.0;
  double speed_mps = 20.0;
  double day_km_low = 200.0, day_km_high = 500.0;
};

// The four routes the depot's locomotives are rostered on, week by week.
const std::vector<RouteKind>& route_kinds();

struct CurveStretch {
  double start_m = 0.0, length_m = 0.0;  // full curvature between the ramps
  double curvature_per_m = 0.0;          // signed: > 0 a right-hand curve
};

struct RouteTrack {
  RouteKind kind;
  double length_m = 0.0;
  std::vector<CurveStretch> curves;                       // in order along the loop
  std::vector<double> wavelength_m, amplitude_mm, phase;  // the alignment's sines
};

// The route's track, drawn from `random`: a 60 km loop.
RouteTrack draw_route_track(const RouteKind& kind, FleetRandom& random);

// Signed curvature (1/m) at `s_m` (any real: the loop repeats).
double curvature_at(const RouteTrack& track, double s_m);

// The track's lateral alignment (mm) at `s_m`.
double alignment_mm(const RouteTrack& track, double s_m);

// Axle `axle` (1 to 6) of a locomotive at `s_m`, at the route's speed; `wear_mm` the mean
// flange wear of its wheelset; `phase`, `phase2` the axle's own hunting phases.
double lateral_shift_mm(const RouteTrack& track, int axle, double s_m, double wear_mm, double phase,
                        double phase2);

// Where axle `axle` is behind the locomotive's leading axle (m).
double axle_offset_m(int axle);

}  // namespace flange::fleet_alt
