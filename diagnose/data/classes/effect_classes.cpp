// SPDX-License-Identifier: MIT
#include "effect_classes.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "selftest_draw.h"

namespace flange::diagnose {
namespace {

// The drifts' reference is the temperature the sensor was calibrated at: a room, 0-40 degC. A
// reference far outside it would let a temperature drift pose as a constant offset.
EffectClass temp_gain_drift() {
  return {
      .name = "temp_gain_drift",
      .search = {{"gain_per_c", -0.01, 0.01}, {"reference_c", 0, 40}},
      .follows = "the temperature",
      // The relative change of the gain there (the effect's factor less 1).
      .level = TemperatureLevel{"gain_change",
                                [](const sim::ParamValues& p, double temp_c) {
                                  return p.at("gain_per_c") * (temp_c - p.at("reference_c"));
                                }},
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        return {{"gain_per_c", d.signed_magnitude(0.5e-3, 3e-3)},
                {"reference_c", d.uniform(15, 25)}};
      },
  };
}

EffectClass temp_offset_drift() {
  return {
      .name = "temp_offset_drift",
      .search = {{"offset_v_per_c", -0.05, 0.05}, {"reference_c", 0, 40}},
      .follows = "the temperature",
      .level = TemperatureLevel{"offset_v",
                                [](const sim::ParamValues& p, double temp_c) {
                                  return p.at("offset_v_per_c") * (temp_c - p.at("reference_c"));
                                }},
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        return {{"offset_v_per_c", d.signed_magnitude(1e-3, 5e-3)},
                {"reference_c", d.uniform(15, 25)}};
      },
  };
}

EffectClass nonlinearity() {
  return {
      .name = "nonlinearity",
      .search = {{"bow_v", -1, 1}, {"s_curve_v", -1, 1}},
      .follows = "the voltage (clearance)",
      .function_of_clearance_alone = true,
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        return {{"bow_v", d.signed_magnitude(0.05, 0.25)},
                {"s_curve_v", d.signed_magnitude(0.03, 0.15)}};
      },
  };
}

EffectClass range_compression() {
  return {
      .name = "range_compression",
      .search = {{"onset_c", -40, 150}, {"knee_drop_v_per_c", 0.0, 0.2}, {"headroom_v", 0.05, 3.0}},
      .follows = "the voltage (clearance)",
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        return {{"onset_c", d.uniform(30, 60)},
                {"knee_drop_v_per_c", d.uniform(0.02, 0.06)},
                {"headroom_v", d.uniform(0.2, 1.0)}};
      },
  };
}

// tau_s > 0: the coil lags the recorded temperature; tau_s < 0: the reading lags the coil.
EffectClass thermal_lag() {
  return {
      .name = "thermal_lag",
      .search = {{"tau_s", -1800, 1800}},
      .follows = "the temperature's rate of change",
      .channel_delay =
          [](const sim::EffectSettings& e) {
            const double tau_s = e.params.at("tau_s");
            return ChannelDelay{.temperature_lag_tau_s = tau_s < 0.0 ? -tau_s : 0.0};
          },
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        return {{"tau_s", d.signed_magnitude(60, 900)}};
      },
  };
}

// skew_s > 0: the temperature channel is late; skew_s < 0: the voltage channel is.
EffectClass channel_skew() {
  return {
      .name = "channel_skew",
      .search = {{"skew_s", -10, 10}},
      .follows = "the clearance's moves",
      .carries_no_level = true,
      .channel_delay =
          [](const sim::EffectSettings& e) {
            return ChannelDelay{.skew = {e.params.at("skew_s"), e.params.at("drift_s_per_h"),
                                         e.params.at("drift_change_s_per_h2")}};
          },
      // A late temperature channel moves the bench voltage by less than the noise (the blower
      // changes the temperature by 0.13 degC/s at most); a late voltage channel shows on every
      // micrometer step. Only the detectable side is drawn.
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        return {{"skew_s", -d.uniform(1.0, 8.0)}};
      },
  };
}

// Solved in closed form (fit_ageing): a line in time within the catalogue's limits, which the
// search ranges state.
EffectClass ageing_drift() {
  return {
      .name = "ageing_drift",
      .search = {{"rate_v_per_day", -2, 2}, {"start_age_days", 0, 3650}},
      .profiled_in_other_fits = true,
      .follows = "the time",
      .age_param = "start_age_days",
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        return {{"rate_v_per_day", d.signed_magnitude(0.5, 2.0)},
                {"start_age_days", d.uniform(0.0, 0.5)}};
      },
  };
}

EffectClass mains_pickup() {
  return {
      .name = "mains_pickup",
      .reported_as_noise = true,
      .pick_note = "a tone: the mains line aliased by the sampling",
      .search = {{"amplitude_v", 0, 1}, {"phase_deg", -180, 180}, {"harmonic_ratio", 0, 1}},
      .follows = "the spectrum",
      .lines_of_each_session = true,
      .carries_no_level = true,
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        return {{"amplitude_v", d.uniform(0.05, 0.3)},
                {"phase_deg", d.uniform(-180, 180)},
                {"harmonic_ratio", d.uniform(0.1, 0.5)}};
      },
  };
}

EffectClass vibration() {
  return {
      .name = "vibration",
      .identification = Identification::kBySignature,
      .follows = "the sensor's sensitivity",
      .is_mount_motion = true,
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        return {{"rms_mm", d.uniform(0.1, 0.5)}};
      },
  };
}

EffectClass adc_quantization() {
  return {
      .name = "adc_quantization",
      .identification = Identification::kBySignature,
      .follows = "the recorded codes",
      .is_converter = true,
      .selftest_draw = [](SelftestDraw& d) -> sim::ParamValues {
        const bool bipolar = d.index(2) == 0;
        return {{"bits", 8 + d.index(5)}, {"v_min", bipolar ? -10.0 : 0.0}, {"v_max", 10.0}};
      },
  };
}

// Not a class the diagnosis looks for: the table an improved twin replays its free shapes with
// (improved_twin/). Recognised by no signature and fitted by nothing, it only stands in the table
// so that a twin holding it can be replayed, its table placed at the sensor's age.
EffectClass tabulated() {
  return {
      .name = sim::tabulated_effect_name(),
      .identification = Identification::kBySignature,
      .follows = "the table",
      .age_param = "start_age_days",
  };
}

// Not a class the diagnosis looks for either: the effect an improved twin holds a thermal lag's
// free shape in volts with (candidates/free_shapes/lag_family.h, VoltsLagFamily), found and
// named as thermal_lag. It stands in the table so that a twin holding it can be replayed.
EffectClass thermal_lag_volts() {
  return {
      .name = "thermal_lag_volts",
      .identification = Identification::kBySignature,
      .follows = "the temperature's rate of change",
  };
}

}  // namespace

const std::vector<EffectClass>& effect_classes() {
  static const std::vector<EffectClass> classes = {
      temp_gain_drift(), temp_offset_drift(), nonlinearity(), range_compression(),
      thermal_lag(),     channel_skew(),      ageing_drift(), mains_pickup(),
      vibration(),       adc_quantization(),  tabulated(),         thermal_lag_volts()};
  return classes;
}

const EffectClass* find_effect_class(const std::string& name) {
  for (const EffectClass& c : effect_classes()) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

const EffectClass& effect_class(const std::string& name) {
  const EffectClass* found = find_effect_class(name);
  if (found == nullptr) throw std::out_of_range("no effect class " + name);
  return *found;
}

std::vector<std::string> bias_classes_in_catalogue_order() {
  std::vector<std::string> names;
  for (const sim::EffectSpec& spec : sim::effect_catalogue()) {
    if (effect_class(spec.name).identification == Identification::kByBias) {
      names.push_back(spec.name);
    }
  }
  return names;
}

ChannelDelay channel_delay_of(const sim::EffectSettings& effect) {
  const EffectClass& c = effect_class(effect.name);
  return c.channel_delay ? c.channel_delay(effect) : ChannelDelay{};
}

namespace {

const std::string& name_of_the_one(bool EffectClass::*property) {
  for (const EffectClass& c : effect_classes()) {
    if (c.*property) return c.name;
  }
  throw std::logic_error("the class table lacks a class it needs");
}

}  // namespace

const std::string& converter_class() { return name_of_the_one(&EffectClass::is_converter); }

bool each_sessions_own(const sim::EffectSettings& effect) {
  const EffectClass& of = effect_class(effect.name);
  return of.is_mount_motion || of.lines_of_each_session;
}

std::vector<sim::EffectSettings> replayed_effects(const std::vector<sim::EffectSettings>& effects) {
  std::vector<sim::EffectSettings> out;
  std::copy_if(effects.begin(), effects.end(), std::back_inserter(out),
               [](const sim::EffectSettings& e) { return !each_sessions_own(e); });
  return out;
}

const std::string& motion_class() { return name_of_the_one(&EffectClass::is_mount_motion); }

}  // namespace flange::diagnose
