// SPDX-License-Identifier: MIT
#include "effect_classes.h"

#include <algorithm>
#include <iterator>
#include <stdexcept>

#include "effect_fit.h"
#include "family_makers.h"
#include "selftest_draw.h"

namespace flange::diagnose {
namespace {

namespace fs = free_shapes;

// The drifts' reference is the temperature the sensor was calibrated at: a room, 0-40 degC. A
// reference far outside it would let a temperature drift pose as a constant offset.
EffectClass temp_gain_drift() {
  return {
      .name = "temp_gain_drift",
      .search = {{"gain_per_c", -0.01, 0.01}, {"reference_c", 0, 40}},
      .fit = fit_by_search,
      .follows = "the temperature",
      .families = {{"temp_gain_drift", "(V - v_min) T", fs::make_temperature_gain_curve},
                   {"temp_gain_drift", "(V - pivot) T", fs::make_pivot_gain}},
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
      .fit = fit_by_search,
      .follows = "the temperature",
      .families = {{"temp_offset_drift", "T", fs::make_temperature_offset_curve}},
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
      .fit = fit_by_search,
      .follows = "the voltage (clearance)",
      .function_of_clearance_alone = true,
      // A periodic curve of the clearance is not weighed on a converter grid: the grid's
      // quantisation error repeats with every LSB of voltage, which the sensor's sensitivity makes
      // a ripple of about LSB / (dV/dd) in the clearance.
      .families = {{"nonlinearity", "V", fs::make_voltage_curve},
                   {"nonlinearity", "d", fs::make_clearance_curve},
                   {"nonlinearity", "d, periodic", fs::make_clearance_ripple,
                    /*weighed_on_a_converter_grid=*/false}},
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
      .fit = fit_by_search,
      .follows = "the voltage (clearance)",
      .families = {{"range_compression", "top of V, T", fs::make_compression_surface},
                   {"range_compression", "V over a moving knee", fs::make_moving_knee}},
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
      .fit = fit_by_search,
      .follows = "the temperature's rate of change",
      .channel_delay =
          [](const sim::EffectSettings& e) {
            const double tau_s = e.params.at("tau_s");
            return ChannelDelay{.temperature_lag_tau_s = tau_s < 0.0 ? -tau_s : 0.0};
          },
      .families = {{"thermal_lag", "lagged T", fs::make_lag}},
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
      .fit = fit_by_search,
      .follows = "the clearance's moves",
      .channel_delay =
          [](const sim::EffectSettings& e) {
            return ChannelDelay{.skew = {e.params.at("skew_s"), e.params.at("drift_s_per_h"),
                                         e.params.at("drift_change_s_per_h2")}};
          },
      .families = {{"channel_skew", "t", fs::make_skew}},
      // The law the free shape found, as the effect's drift; the free shape's voltage is sampled
      // late or early, the effect's makes the temperature late where the skew turns positive, so
      // only a law that keeps the voltage late all session is the effect.
      .member_of_shape = [](const FreeShapeFit& shape) -> std::optional<sim::ParamValues> {
        const auto& p = shape.params;
        if (p.count("skew_s_most") == 0 || p.at("skew_s_most") > 0.0) return std::nullopt;
        return sim::ParamValues{{"skew_s", p.at("skew_s_at_start")},
                                {"drift_s_per_h", p.at("drift_s_per_h")},
                                {"drift_change_s_per_h2", p.at("drift_change_s_per_h2")}};
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
      .fit = fit_ageing,
      .profiled_in_other_fits = true,
      .follows = "the time",
      .age_param = "start_age_days",
      .families = {{"ageing_drift", "age, continuing", fs::make_continuing_ageing},
                   {"ageing_drift", "age, settled", fs::make_settled_age_curve}},
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
      .fit = fit_mains,
      .follows = "the spectrum",
      .lines_of_each_session = true,
      .families = {{"mains_pickup", "aliased lines", fs::make_mains_lines}},
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

}  // namespace

const std::vector<EffectClass>& effect_classes() {
  static const std::vector<EffectClass> classes = {
      temp_gain_drift(), temp_offset_drift(), nonlinearity(), range_compression(),
      thermal_lag(),     channel_skew(),      ageing_drift(), mains_pickup(),
      vibration(),       adc_quantization(),  tabulated()};
  return classes;
}

const EffectClass& effect_class(const std::string& name) {
  for (const EffectClass& c : effect_classes()) {
    if (c.name == name) return c;
  }
  throw std::out_of_range("no effect class " + name);
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

std::vector<FreeShapeFamily> all_free_shape_families() {
  std::vector<FreeShapeFamily> families;
  for (const EffectClass& c : effect_classes()) {
    families.insert(families.end(), c.families.begin(), c.families.end());
  }
  return families;
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
