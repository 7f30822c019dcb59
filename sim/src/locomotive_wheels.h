// SPDX-License-Identifier: MIT
// What is particular to each wheel of a six-axle (Co-Co) locomotive: where it sits (axle and
// side, and so how far behind the leading axle it meets the track), how worn its flange is, and
// the seed of its sensor twin. Channel c is axle c / 2 + 1, left for even c, right for odd c.
#pragma once

#include <cstdint>
#include <string>

namespace flange::sim {

inline constexpr int kLocomotiveAxles = 6;
inline constexpr int kMaxWheels = 2 * kLocomotiveAxles;  // channels 0 to 11

// The lap's curve turns right, so the left rail is the outer one: in the curve the wheelset
// shifts towards the left, closing the left sensor's gap and opening the right one's.
enum class WheelSide { kLeft, kRight };

struct WheelPosition {
  int axle = 1;  // 1 (leading) to 6
  WheelSide side = WheelSide::kLeft;
};

// channel in 0 .. kMaxWheels - 1.
WheelPosition wheel_position(int channel);

// "left" or "right".
const char* side_name(WheelSide side);

// Axles along the locomotive. The thesis gives no geometry; these are typical of a Co-Co
// locomotive of its class: three axles per bogie 2.0 m apart, bogie centres 11.0 m apart.
struct AxleLayout {
  double axle_spacing_m = 2.0;    // > 0: between neighbouring axles of one bogie
  double bogie_centres_m = 11.0;  // > 2 axle_spacing_m: between the two bogies' middle axles
};

// Distance of `axle` (1 to 6) behind the leading axle, in m: 0, 2, 4, 11, 13, 15 by default.
double axle_offset_m(const AxleLayout& layout, int axle);

// A flange's state over the run: the static clearance at the start and how far wear opens it
// by the end (linearly: service wear of weeks compressed into the run).
struct FlangeWear {
  double initial_clearance_mm = 0.0;
  double wear_over_run_mm = 0.0;
};

// How the wheels' flanges differ from the nominal one. Each wheel c >= 1 draws two numbers
// u1, u2 uniform in [0, 1) from a stream fixed by its channel (not by --seed: two seeds are
// two measurements of the same locomotive):
//   initial clearance = nominal + initial_clearance_spread_mm * u1
//   wear over the run = nominal * side share * (1 - wear_spread * u2)
// with side share 1 on the left (outer: its flange runs against the rail in the curve) and
// inner_wear_share on the right. Channel 0 (axle 1 left) keeps the nominal flange, so a
// one-wheel locomotive is the single-wheel run.
struct WheelSpread {
  double initial_clearance_spread_mm = 0.5;  // >= 0; nominal 4.0 mm -> 4.0 to 4.5 mm
  double wear_spread = 0.4;                  // in [0, 1]; nominal 4.5 mm -> 2.7 to 4.5 mm left
  double inner_wear_share = 0.5;             // in [0, 1]; ... and 1.35 to 2.25 mm right
};

// The flange of wheel `channel` (0 to 11) around the nominal one.
FlangeWear flange_wear(const FlangeWear& nominal, const WheelSpread& spread, int channel);

// Seed of wheel `channel`'s sensor twin: `seed` itself for channel 0 (the single-wheel run's),
// an independent stream of it for every other channel.
std::uint64_t wheel_seed(std::uint64_t seed, int channel);

}  // namespace flange::sim
