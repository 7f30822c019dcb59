// SPDX-License-Identifier: MIT
#include "fleet_alt_track.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace flange::fleet_alt {
namespace {

constexpr double kLoopM = 60000.0;
constexpr double kRampM = 50.0;
constexpr double kCurveLowM = 250.0, kCurveHighM = 900.0;  // a curve's full-curvature length
constexpr double kMaxShiftMm = 1.8;                        // the axle box's lateral play
constexpr double kWheelRadiusM = 0.525, kContactHalfGaugeM = 0.75;
constexpr double kTwoPi = 2.0 * std::numbers::pi;

// The steering share of each axle (1 to 6): two three-axle bogies.
constexpr std::array<double, 6> kAxleShare = {1.3, 0.7, 1.0, 1.3, 0.7, 1.0};
constexpr std::array<double, 6> kAxleOffsetM = {0.0, 2.0, 4.0, 11.0, 13.0, 15.0};

double wrapped(double s_m, double length_m) {
  const double s = std::fmod(s_m, length_m);
  return s < 0.0 ? s + length_m : s;
}

// 1 inside the curve's full curvature, ramping to 0 over kRampM either side.
double ramp_weight(const CurveStretch& curve, double s) {
  if (s < curve.start_m - kRampM || s > curve.start_m + curve.length_m + kRampM) return 0.0;
  if (s < curve.start_m) return (s - (curve.start_m - kRampM)) / kRampM;
  if (s > curve.start_m + curve.length_m)
    return (curve.start_m + curve.length_m + kRampM - s) / kRampM;
  return 1.0;
}

}  // namespace

const std::vector<RouteKind>& route_kinds() {
  static const std::vector<RouteKind> kinds = {
      {"plain", 0.12, 0.5, 700.0, 1600.0, 24.0, 350.0, 700.0},
      {"escarpment", 0.45, 0.5, 250.0, 500.0, 15.0, 150.0, 350.0},
      {"coast", 0.25, 0.8, 400.0, 900.0, 20.0, 250.0, 550.0},
      {"branch", 0.30, 0.2, 300.0, 700.0, 17.0, 200.0, 450.0},
  };
  return kinds;
}

RouteTrack draw_route_track(const RouteKind& kind, FleetRandom& random) {
  RouteTrack track;
  track.kind = kind;
  track.length_m = kLoopM;
  const double mean_curve_m = 0.5 * (kCurveLowM + kCurveHighM) + 2.0 * kRampM;
  const double mean_tangent_m = mean_curve_m * (1.0 - kind.curve_share) / kind.curve_share;
  double s = 0.0;
  while (true) {
    s += kRampM + mean_tangent_m * -std::log(random.unit());  // an exponential tangent
    const double length = random.uniform(kCurveLowM, kCurveHighM);
    if (s + length + 2.0 * kRampM > kLoopM) break;
    const double hand = random.chance(kind.right_hand_share) ? 1.0 : -1.0;
    const double radius = random.uniform(kind.radius_low_m, kind.radius_high_m);
    track.curves.push_back({s + kRampM, length, hand / radius});
    s += length + 2.0 * kRampM;
  }
  for (int k = 0; k < 12; ++k) {
    track.wavelength_m.push_back(random.uniform(8.0, 70.0));
    track.amplitude_mm.push_back(0.05 * random.unit());
    track.phase.push_back(kTwoPi * random.unit());
  }
  return track;
}

double curvature_at(const RouteTrack& track, double s_m) {
  const double s = wrapped(s_m, track.length_m);
  const auto after = std::upper_bound(
      track.curves.begin(), track.curves.end(), s,
      [](double at, const CurveStretch& curve) { return at < curve.start_m - kRampM; });
  if (after == track.curves.begin()) return 0.0;
  const CurveStretch& curve = *std::prev(after);
  return curve.curvature_per_m * ramp_weight(curve, s);
}

double alignment_mm(const RouteTrack& track, double s_m) {
  double y = 0.0;
  for (std::size_t k = 0; k < track.wavelength_m.size(); ++k) {
    y += track.amplitude_mm[k] * std::sin(kTwoPi * s_m / track.wavelength_m[k] + track.phase[k]);
  }
  return y;
}

double lateral_shift_mm(const RouteTrack& track, int axle, double s_m, double wear_mm, double phase,
                        double phase2) {
  const double share = kAxleShare.at(static_cast<std::size_t>(axle - 1));
  const double k = curvature_at(track, s_m);
  const double v = track.kind.speed_mps;
  double y = 0.7 * alignment_mm(track, s_m);
  if (k != 0.0) {
    const double hand = k > 0.0 ? 1.0 : -1.0;
    const double quasi_static = 0.35 * std::min(1.0, 1500.0 * std::abs(k)) +
                                1.6 * std::max(0.0, v * v * std::abs(k) - 0.45);
    return y + hand * std::min(kMaxShiftMm, share * quasi_static);
  }
  const double conicity = 0.06 + 0.025 * wear_mm;
  const double wavelength = kTwoPi * std::sqrt(kWheelRadiusM * kContactHalfGaugeM / conicity);
  const double amplitude = 0.4 * std::clamp((v - 15.0) / 8.0, 0.0, 1.0) *
                           (0.6 + 0.4 * std::sin(kTwoPi * s_m / 900.0 + phase2));
  return y + amplitude * std::sin(kTwoPi * s_m / wavelength + phase);
}

double axle_offset_m(int axle) { return kAxleOffsetM.at(static_cast<std::size_t>(axle - 1)); }

}  // namespace flange::fleet_alt
