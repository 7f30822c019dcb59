// SPDX-License-Identifier: MIT
#include "effect_catalogue.h"

#include <fmt/format.h>

#include <cmath>

#include "effects/effects.h"
#include "gaussian_source.h"
#include "sim_error.h"

namespace flange::sim {

const std::vector<EffectSpec>& effect_catalogue() {
  static const std::vector<EffectSpec> catalogue = {
      vibration_effect(),         thermal_lag_effect(),       nonlinearity_effect(),
      temp_gain_drift_effect(),   temp_offset_drift_effect(), ageing_drift_effect(),
      range_compression_effect(), thermal_lag_volts_effect(), mains_pickup_effect(),
      channel_skew_effect(),      tabulated_effect(),         adc_quantization_effect(),
  };
  return catalogue;
}

int catalogue_index(const std::string& name) {
  const std::vector<EffectSpec>& catalogue = effect_catalogue();
  for (std::size_t i = 0; i < catalogue.size(); ++i) {
    if (catalogue[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

ChainStage chain_stage_of(const std::string& name) {
  return effect_catalogue()[static_cast<std::size_t>(catalogue_index(name))].stage;
}

std::string effect_names() {
  std::string names;
  for (const EffectSpec& spec : effect_catalogue()) {
    names += (names.empty() ? "" : ", ") + spec.name;
  }
  return names;
}

std::string describe_range(const ParamSpec& param) {
  std::string text = fmt::format("[{}, {}]", param.min, param.max);
  if (!param.unit.empty()) text += " " + param.unit;
  if (param.integer) text += " (integer)";
  return text;
}

EffectSettings make_effect_settings(const std::string& name, const ParamValues& values,
                                    const std::string& where) {
  const int index = catalogue_index(name);
  if (index < 0) {
    throw BadArgument(
        fmt::format("{}: unknown effect '{}'; known effects: {}", where, name, effect_names()));
  }
  const EffectSpec& spec = effect_catalogue()[static_cast<std::size_t>(index)];
  EffectSettings settings{name, {}};
  for (const ParamSpec& param : spec.params) settings.params[param.key] = param.default_value;
  for (const auto& [key, value] : values) {
    const ParamSpec* param = nullptr;
    for (const ParamSpec& candidate : spec.params) {
      if (candidate.key == key) param = &candidate;
    }
    if (param == nullptr) {
      std::string keys;
      for (const ParamSpec& candidate : spec.params)
        keys += (keys.empty() ? "" : ", ") + candidate.key;
      throw BadArgument(
          fmt::format("{}: unknown key '{}' for effect {}; its keys: {}", where, key, name, keys));
    }
    if (!std::isfinite(value) || value < param->min || value > param->max ||
        (param->integer && value != std::round(value))) {
      throw BadArgument(fmt::format("{}: {} = {} is outside its valid range {}", where, key, value,
                                    describe_range(*param)));
    }
    settings.params[key] = value;
  }
  if (spec.check_together) {
    const std::string problem = spec.check_together(settings.params);
    if (!problem.empty()) throw BadArgument(fmt::format("{}: {} ({})", where, problem, name));
  }
  return settings;
}

std::unique_ptr<Effect> make_effect(const EffectSettings& settings, double v_min_v, double v_max_v,
                                    std::uint64_t twin_seed) {
  const int index = catalogue_index(settings.name);
  if (index < 0) throw BadArgument(fmt::format("unknown effect '{}'", settings.name));
  // Stream 0 is the twin's white noise; effect i draws from stream i + 1.
  const EffectContext context{v_min_v, v_max_v,
                              derive_seed(twin_seed, static_cast<std::uint64_t>(index) + 1),
                              settings.table};
  return effect_catalogue()[static_cast<std::size_t>(index)].make(settings.params, context);
}

}  // namespace flange::sim
