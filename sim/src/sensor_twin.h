// SPDX-License-Identifier: MIT
// The sensor twin: what the inductive sensor, thermocouple and DAQ record for a given clearance
// and temperature. The nominal model (a calibration polynomial, inverted) plus white noise,
// plus any switched-on effects, each applied at its place in the signal chain.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "chain_sample.h"
#include "effect.h"
#include "effect_catalogue.h"
#include "gaussian_source.h"
#include "polynomial_sensor_model.h"

namespace flange::sim {

// Thesis Table 4-1 gives the repeatability (relative standard deviation, V) at 12 temperatures,
// 0.011 to 0.133 V. Pooled by eq. 4.2 with equal sample counts it is their RMS: 0.0703 V.
inline constexpr double kThesisRepeatabilityRmsV = 0.07028;

struct NoiseSettings {
  double voltage_std_v = kThesisRepeatabilityRmsV;  // >= 0, <= 10: white noise on the voltage
  double temperature_std_c = 0.0;  // >= 0, <= 100: on the thermocouple (the thesis gives none)
  // >= 0, LSB / sqrt(12) <= voltage_std_v: of the voltage noise, the rounding of a converter grid
  // with this LSB whose codes the twin does not replay (0: none). The twin adds white noise at
  // voltage_std_v either way; `flange diagnose` against the twin takes that grid as held.
  double rounding_lsb_v = 0.0;
  bool operator==(const NoiseSettings&) const = default;
};

struct TwinConfig {
  PolynomialSensorModel nominal = PolynomialSensorModel::thesis_eq_3_14();
  NoiseSettings noise;
  std::vector<EffectSettings> effects;  // at most one per name; run in chain order
  // What made the twin and what it could not hold (the twin file's "notes"); the twin ignores them.
  std::vector<std::string> notes;
};

// Throws BadArgument when noise levels are out of range or an effect appears twice.
void check_twin_config(const TwinConfig& config);

struct RailClipCounts {
  std::int64_t low = 0;   // samples whose sensor output sat on the bottom rail (0 V)
  std::int64_t high = 0;  // ... on the top rail (10 V)
};

class SensorTwin {
 public:
  // Same config and seed, same readings, sample for sample (on one toolchain and libm).
  SensorTwin(const TwinConfig& config, std::uint64_t seed);

  // One sample; call with increasing t_s. Throws std::invalid_argument on non-finite truth.
  Reading step(const TrueState& truth);

  const RailClipCounts& clip_counts() const { return clip_counts_; }

 private:
  PolynomialSensorModel nominal_;
  NoiseSettings noise_;
  // Effects in chain order; [stage_end_[s-1], stage_end_[s]) belong to stage s.
  std::vector<std::unique_ptr<Effect>> effects_;
  std::vector<std::size_t> stage_end_;
  GaussianSource voltage_noise_;
  GaussianSource temperature_noise_;
  RailClipCounts clip_counts_;

  void apply_stage(ChainStage stage, ChainSample& sample);
};

}  // namespace flange::sim
