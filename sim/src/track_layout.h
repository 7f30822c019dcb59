// SPDX-License-Identifier: MIT
// The thesis's test track (3.3.4), run over and over: a tangent carrying one lateral
// irregularity, a transition, a constant-radius curve with cant, a transition, a tangent.
// It gives the two inputs of the wheelset's lateral dynamics: the curve's unbalanced lateral
// acceleration and the irregularity's lateral acceleration, both as the locomotive meets them.
#pragma once

namespace flange::sim {

struct TrackLayout {
  double speed_mps = 20.0;                 // 3.3.2: 20 m/s (72 km/h)
  double tangent_in_m = 10.0;              // 3.3.4: tangent of 10 m
  double transition_m = 50.0;              // 3.3.4: transitions of 50 m before and after the curve
  double curve_m = 300.0;                  // 3.3.4: length of the constant-radius curve
  double radius_m = 300.0;                 // brief and 3.3.4: R = 300 m
  double cant_m = 0.09;                    // 3.3.4: cant H = 0.09 m
  double tangent_out_m = 10.0;             // the lap closes with another 10 m of tangent
  double rail_spacing_m = 1.5;             // distance between rail-head centres (1435 mm gauge)
  double irregularity_amplitude_m = 0.02;  // 3.3.4: 20 mm ...
  double irregularity_length_m = 10.0;     // ... over 10 m, at the start of the track
};

// Length of one lap in metres.
double lap_length_m(const TrackLayout& track);

// Share of the full curve at lap position s (0 on tangents, 1 in the curve, linear in the
// clothoid transitions, where curvature and cant both ramp).
double curve_share(const TrackLayout& track, double lap_position_m);

// Lateral acceleration the cant does not balance in the full curve, in m/s^2:
// v^2 / R - g H / s (about 0.745 m/s^2 for the thesis track).
double unbalanced_acceleration_mps2(const TrackLayout& track);

// The lateral alignment irregularity at lap position s: a full cosine bump of the given
// amplitude and length, y = A/2 (1 - cos(2 pi s / L)) for 0 <= s <= L, in metres.
double irregularity_m(const TrackLayout& track, double lap_position_m);

// Its lateral acceleration as the vehicle runs over it at speed v: v^2 y''(s), in m/s^2.
double irregularity_acceleration_mps2(const TrackLayout& track, double lap_position_m);

}  // namespace flange::sim
