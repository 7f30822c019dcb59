// SPDX-License-Identifier: MIT
#include "null_replica_twin.h"

#include <algorithm>
#include <memory>
#include <optional>

#include "effect_classes.h"

namespace flange::diagnose {

NullReplica null_replica(const TwinReplay& replay, const DiagnoseOptions& given,
                         const WhiteNoise& white) {
  const auto is_converter = [](const sim::EffectSettings& e) {
    return effect_class(e.name).is_converter;
  };
  const std::vector<sim::EffectSettings>& held = given.twin.effects;
  const auto converter = std::find_if(held.begin(), held.end(), is_converter);
  const bool motion = std::any_of(held.begin(), held.end(), [](const sim::EffectSettings& e) {
    return effect_class(e.name).is_mount_motion;
  });
  if (!motion && converter == held.end()) return {};
  std::vector<sim::EffectSettings> before_converter = held;
  std::erase_if(before_converter, is_converter);
  std::optional<sim::EffectSettings> rounding;
  if (converter != held.end()) rounding = *converter;
  return [&replay, &white, before_converter, rounding](std::uint64_t seed,
                                                       const std::vector<double>& z) {
    std::vector<double> v = replay.voltage(before_converter, seed);
    if (!rounding) {
      for (std::size_t i = 0; i < v.size(); ++i) v[i] = white.noisy(v[i], z[i]);
      return v;
    }
    const std::unique_ptr<sim::Effect> rounds =
        sim::make_effect(*rounding, replay.v_min_v(), replay.nominal().v_max_v(), seed);
    for (std::size_t i = 0; i < v.size(); ++i) {
      sim::ChainSample sample;
      sample.t_s = replay.times()[i];
      sample.voltage_v = v[i] + white.analog_std_v * z[i];
      rounds->apply(sample);
      v[i] = sample.voltage_v;
    }
    return v;
  };
}

}  // namespace flange::diagnose
