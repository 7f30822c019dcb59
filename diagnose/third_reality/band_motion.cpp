// SPDX-License-Identifier: MIT
#include "band_motion.h"

#include <cmath>
#include <numbers>

namespace flange::third_reality {
namespace {

constexpr int kNarrowBandComponents = 40;

}  // namespace

void BandMotion::build() {
  ThirdRandom random(static_cast<std::uint64_t>(seed));
  hz.clear();
  amplitude.clear();
  phase.clear();
  const int count = narrow_band ? kNarrowBandComponents : 1 + random.below(3);
  double power = 0.0;
  for (int j = 0; j < count; ++j) {
    hz.push_back(narrow_band ? centre_hz + bandwidth_hz * random.normal()
                             : centre_hz * (j == 0 ? 1.0 : random.uniform(1.1, 2.7)));
    amplitude.push_back(narrow_band ? random.normal() : random.uniform(0.3, 1.0));
    phase.push_back(random.uniform(0.0, 2.0 * std::numbers::pi));
    power += amplitude.back() * amplitude.back() / 2.0;
  }
  for (double& a : amplitude) a /= std::sqrt(power);
}

double BandMotion::operator()(double t_s) const {
  double sum = 0.0;
  for (std::size_t j = 0; j < hz.size(); ++j) {
    sum += amplitude[j] * std::sin(2.0 * std::numbers::pi * hz[j] * t_s + phase[j]);
  }
  return sum;
}

double alias_hz(double f_hz, double fs_hz) {
  return std::abs(f_hz - fs_hz * std::round(f_hz / fs_hz));
}

bool shows_as_a_line(double f_hz, double fs_hz, double margin_hz) {
  const double a = alias_hz(f_hz, fs_hz);
  return a >= margin_hz && a <= fs_hz / 2.0 - margin_hz;
}

BandMotion draw_band_motion(double fs_hz, ThirdRandom& random) {
  BandMotion motion;
  motion.narrow_band = random.chance(0.5);
  motion.bandwidth_hz = random.log_uniform(0.02, 0.4);
  const double lo = fs_hz <= 12.5 ? fs_hz / 2.0 + 0.5 : 2.0;
  const double hi = fs_hz <= 12.5 ? 45.0 : std::min(45.0, fs_hz / 2.0 - 1.0);
  do {
    motion.centre_hz = random.uniform(lo, hi);
  } while (!shows_as_a_line(motion.centre_hz, fs_hz, 0.4));
  motion.seed = random.child_seed();
  motion.build();
  return motion;
}

void put_band_motion(const BandMotion& motion, Params& params) {
  params["narrow_band"] = motion.narrow_band ? 1.0 : 0.0;
  params["centre_hz"] = motion.centre_hz;
  params["bandwidth_hz"] = motion.bandwidth_hz;
  params["band_seed"] = motion.seed;
}

BandMotion get_band_motion(const Params& params) {
  BandMotion motion;
  motion.narrow_band = params.at("narrow_band") != 0.0;
  motion.centre_hz = params.at("centre_hz");
  motion.bandwidth_hz = params.at("bandwidth_hz");
  motion.seed = params.at("band_seed");
  motion.build();
  return motion;
}

}  // namespace flange::third_reality
