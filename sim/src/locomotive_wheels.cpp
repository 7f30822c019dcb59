// SPDX-License-Identifier: MIT
#include "locomotive_wheels.h"

#include <fmt/format.h>

#include <stdexcept>

#include "gaussian_source.h"

namespace flange::sim {
namespace {

constexpr int kAxlesPerBogie = 3;
// Stream numbers of the wheels, far from the twin's own (0 to about 11, and 1000), so that a
// wheel's twin seed never equals a stream the twin derives from the same seed.
constexpr std::uint64_t kWheelSeedStream = 2000;
// The wear spread's fixed seed: the locomotive's wheels are the same whatever --seed is.
constexpr std::uint64_t kWheelSpreadSeed = 0x10C0;

void check_channel(int channel) {
  if (channel < 0 || channel >= kMaxWheels) {
    throw std::out_of_range(fmt::format("wheel channel {} is outside its valid range 0 to {}",
                                        channel, kMaxWheels - 1));
  }
}

}  // namespace

WheelPosition wheel_position(int channel) {
  check_channel(channel);
  return {channel / 2 + 1, channel % 2 == 0 ? WheelSide::kLeft : WheelSide::kRight};
}

const char* side_name(WheelSide side) { return side == WheelSide::kLeft ? "left" : "right"; }

double axle_offset_m(const AxleLayout& layout, int axle) {
  const int index = axle - 1;
  const int bogie = index / kAxlesPerBogie;
  const int in_bogie = index % kAxlesPerBogie;
  return bogie * layout.bogie_centres_m + in_bogie * layout.axle_spacing_m;
}

FlangeWear flange_wear(const FlangeWear& nominal, const WheelSpread& spread, int channel) {
  const WheelPosition position = wheel_position(channel);
  if (channel == 0) return nominal;
  GaussianSource draws(derive_seed(kWheelSpreadSeed, static_cast<std::uint64_t>(channel)));
  const double u1 = draws.uniform();
  const double u2 = draws.uniform();
  const double side_share = position.side == WheelSide::kLeft ? 1.0 : spread.inner_wear_share;
  return {nominal.initial_clearance_mm + spread.initial_clearance_spread_mm * u1,
          nominal.wear_over_run_mm * side_share * (1.0 - spread.wear_spread * u2)};
}

std::uint64_t wheel_seed(std::uint64_t seed, int channel) {
  check_channel(channel);
  if (channel == 0) return seed;
  return derive_seed(seed, kWheelSeedStream + static_cast<std::uint64_t>(channel));
}

}  // namespace flange::sim
