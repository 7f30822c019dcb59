// SPDX-License-Identifier: MIT
#include "track_layout.h"

#include <cmath>
#include <numbers>

namespace flange::sim {
namespace {

constexpr double kGravityMps2 = 9.81;

}  // namespace

double lap_length_m(const TrackLayout& track) {
  return track.tangent_in_m + 2.0 * track.transition_m + track.curve_m + track.tangent_out_m;
}

double curve_share(const TrackLayout& track, double s) {
  const double entry = track.tangent_in_m;
  const double full = entry + track.transition_m;
  const double exit = full + track.curve_m;
  const double end = exit + track.transition_m;
  if (s <= entry || s >= end) return 0.0;
  if (s < full) return (s - entry) / track.transition_m;
  if (s <= exit) return 1.0;
  return (end - s) / track.transition_m;
}

double unbalanced_acceleration_mps2(const TrackLayout& track) {
  return track.speed_mps * track.speed_mps / track.radius_m -
         kGravityMps2 * track.cant_m / track.rail_spacing_m;
}

double irregularity_m(const TrackLayout& track, double s) {
  if (s < 0.0 || s > track.irregularity_length_m) return 0.0;
  const double phase = 2.0 * std::numbers::pi * s / track.irregularity_length_m;
  return 0.5 * track.irregularity_amplitude_m * (1.0 - std::cos(phase));
}

double irregularity_acceleration_mps2(const TrackLayout& track, double s) {
  if (s < 0.0 || s > track.irregularity_length_m) return 0.0;
  const double wavenumber = 2.0 * std::numbers::pi / track.irregularity_length_m;
  return track.speed_mps * track.speed_mps * 0.5 * track.irregularity_amplitude_m * wavenumber *
         wavenumber * std::cos(wavenumber * s);
}

}  // namespace flange::sim
