// SPDX-License-Identifier: MIT
#include "sensor_twin.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "sim_error.h"

namespace flange::sim {
namespace {

constexpr std::size_t kStageCount = static_cast<std::size_t>(ChainStage::kAcquisition) + 1;
// Random streams: 0 is the voltage noise, 1..N the effects (catalogue index + 1); the
// temperature noise takes one far beyond them.
constexpr std::uint64_t kTemperatureNoiseStream = 1000;

}  // namespace

void check_twin_config(const TwinConfig& config) {
  const NoiseSettings& noise = config.noise;
  if (!std::isfinite(noise.voltage_std_v) || noise.voltage_std_v < 0.0 ||
      noise.voltage_std_v > 10.0) {
    throw BadArgument(fmt::format("noise.voltage_std_v = {} is outside its valid range [0, 10] V",
                                  noise.voltage_std_v));
  }
  if (!std::isfinite(noise.temperature_std_c) || noise.temperature_std_c < 0.0 ||
      noise.temperature_std_c > 100.0) {
    throw BadArgument(
        fmt::format("noise.temperature_std_c = {} is outside its valid range [0, 100] degC",
                    noise.temperature_std_c));
  }
  const double rounding_std_v = noise.rounding_lsb_v / std::sqrt(12.0);
  if (!std::isfinite(noise.rounding_lsb_v) || noise.rounding_lsb_v < 0.0 ||
      rounding_std_v > noise.voltage_std_v * (1.0 + 1e-9)) {
    throw BadArgument(fmt::format(
        "noise.rounding_lsb_v = {} is outside its valid range [0, {:.6g}] V: its rounding "
        "(LSB / sqrt(12)) is part of noise.voltage_std_v = {} V",
        noise.rounding_lsb_v, noise.voltage_std_v * std::sqrt(12.0), noise.voltage_std_v));
  }
  std::set<std::string> seen;
  for (const EffectSettings& effect : config.effects) {
    if (!seen.insert(effect.name).second) {
      throw BadArgument(fmt::format("effect {} is switched on twice", effect.name));
    }
  }
}

SensorTwin::SensorTwin(const TwinConfig& config, std::uint64_t seed)
    : nominal_(config.nominal),
      noise_(config.noise),
      voltage_noise_(derive_seed(seed, 0)),
      temperature_noise_(derive_seed(seed, kTemperatureNoiseStream)) {
  check_twin_config(config);
  std::vector<const EffectSettings*> ordered;
  for (const EffectSettings& effect : config.effects) ordered.push_back(&effect);
  std::sort(ordered.begin(), ordered.end(), [](const EffectSettings* a, const EffectSettings* b) {
    return catalogue_index(a->name) < catalogue_index(b->name);
  });
  stage_end_.assign(kStageCount, 0);
  for (const EffectSettings* effect : ordered) {
    effects_.push_back(make_effect(*effect, nominal_.v_min_v(), nominal_.v_max_v(), seed));
    const ChainStage stage = chain_stage_of(effect->name);
    // The catalogue is in stage order, so each stage's effects are contiguous.
    for (std::size_t s = static_cast<std::size_t>(stage); s < kStageCount; ++s) {
      stage_end_[s] = effects_.size();
    }
  }
}

void SensorTwin::apply_stage(ChainStage stage, ChainSample& sample) {
  const auto s = static_cast<std::size_t>(stage);
  const std::size_t begin = s == 0 ? 0 : stage_end_[s - 1];
  for (std::size_t i = begin; i < stage_end_[s]; ++i) effects_[i]->apply(sample);
}

Reading SensorTwin::step(const TrueState& truth) {
  if (!std::isfinite(truth.t_s) || !std::isfinite(truth.clearance_mm) ||
      !std::isfinite(truth.temperature_c)) {
    throw std::invalid_argument(
        fmt::format("sensor twin: non-finite truth at t = {} s", truth.t_s));
  }
  ChainSample sample;
  sample.t_s = truth.t_s;
  sample.clearance_mm = truth.clearance_mm;
  sample.ambient_c = sample.coil_c = sample.thermocouple_c = truth.temperature_c;

  apply_stage(ChainStage::kMount, sample);
  apply_stage(ChainStage::kThermal, sample);

  const VoltageSolution nominal = nominal_.voltage_for(sample.clearance_mm, sample.coil_c);
  sample.voltage_v = nominal.volts;
  sample.clip = nominal.clip;
  apply_stage(ChainStage::kSensor, sample);
  // The sensor's output stage cannot leave its supply-limited range.
  if (sample.voltage_v < nominal_.v_min_v()) {
    sample.voltage_v = nominal_.v_min_v();
    sample.clip = RailClip::kLow;
  } else if (sample.voltage_v > nominal_.v_max_v()) {
    sample.voltage_v = nominal_.v_max_v();
    sample.clip = RailClip::kHigh;
  }

  if (noise_.voltage_std_v > 0.0) {
    sample.voltage_v += noise_.voltage_std_v * voltage_noise_.standard_normal();
  }
  if (noise_.temperature_std_c > 0.0) {
    sample.thermocouple_c += noise_.temperature_std_c * temperature_noise_.standard_normal();
  }
  apply_stage(ChainStage::kWiring, sample);
  apply_stage(ChainStage::kAcquisition, sample);

  if (sample.clip == RailClip::kLow) ++clip_counts_.low;
  if (sample.clip == RailClip::kHigh) ++clip_counts_.high;
  return {sample.t_s, sample.thermocouple_c, sample.voltage_v, sample.clip};
}

}  // namespace flange::sim
