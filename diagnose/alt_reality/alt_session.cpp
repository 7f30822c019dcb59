// SPDX-License-Identifier: MIT
#include "alt_session.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "alt_classes.h"
#include "alt_sensor.h"

namespace flange::alt_reality {
namespace {

using EffectChain = std::vector<std::unique_ptr<AltEffect>>;

EffectChain build_chain(const SessionPlan& plan, const std::vector<AltEffectDraw>& effects) {
  EffectChain chain;
  for (const AltEffectDraw& draw : effects) chain.push_back(make_alt_effect(draw, {&plan}));
  return chain;
}

AltSample sample_at(const SessionPlan& plan, double t_s) {
  AltSample s;
  s.t_s = t_s;
  s.age_s = plan.start_age_s + t_s;
  s.clearance_mm = micrometer_mm(plan.micrometer, t_s);
  s.ambient_c = s.coil_c = s.thermocouple_c = ambient_c(plan.heating, t_s);
  return s;
}

// The voltage channel: the whole chain at `instant_s` (the stamped time less any skew).
double voltage_at(const SessionPlan& plan, EffectChain& chain, double instant_s, double noise_v) {
  AltSample s = sample_at(plan, instant_s);
  for (auto& e : chain) e->mount(s);
  for (auto& e : chain) e->coil_temperature(s);
  s.voltage_v = ideal_sensor_voltage(s.clearance_mm, s.coil_c);
  for (auto& e : chain) e->characteristic(s);
  s.voltage_v = std::clamp(s.voltage_v, kSensorLowV, kSensorHighV) + noise_v;
  for (auto& e : chain) e->cable(s);
  for (auto& e : chain) e->converter(s);
  return s.voltage_v;
}

double temperature_at(const SessionPlan& plan, EffectChain& chain, double t_s, double noise_c) {
  AltSample s = sample_at(plan, t_s);
  for (auto& e : chain) e->reading_temperature(s);
  const double step = plan.thermocouple_resolution_c;
  return step * std::round((s.thermocouple_c + noise_c) / step);
}

}  // namespace

double to_six_decimals(double value) { return std::round(value * 1e6) / 1e6; }

AltRecording render_session(const SessionPlan& plan, const std::vector<AltEffectDraw>& effects,
                            bool with_noise) {
  EffectChain voltage_chain = build_chain(plan, effects);
  EffectChain temperature_chain = build_chain(plan, effects);
  AltRandom voltage_noise(plan.noise_seed);
  AltRandom temperature_noise(plan.noise_seed ^ 0x9e3779b97f4a7c15ULL);
  const auto samples = static_cast<std::size_t>(std::floor(plan.duration_s * plan.fs_hz)) + 1;
  AltRecording r;
  for (std::size_t k = 0; k < samples; ++k) {
    const double t_s = to_six_decimals(static_cast<double>(k) / plan.fs_hz);
    double delay_s = 0.0;
    for (const auto& e : voltage_chain) delay_s += e->voltage_delay_s(t_s);
    const double v_noise = with_noise ? plan.noise_v * voltage_noise.normal() : 0.0;
    const double t_noise =
        with_noise ? plan.thermocouple_noise_c * temperature_noise.normal() : 0.0;
    r.t_s.push_back(t_s);
    r.clearance_mm.push_back(to_six_decimals(micrometer_mm(plan.micrometer, t_s)));
    r.temp_c.push_back(to_six_decimals(temperature_at(plan, temperature_chain, t_s, t_noise)));
    r.voltage_v.push_back(to_six_decimals(voltage_at(plan, voltage_chain, t_s - delay_s, v_noise)));
  }
  return r;
}

nlohmann::json session_plan_json(const SessionPlan& plan) {
  return {{"fs_hz", plan.fs_hz},
          {"duration_s", plan.duration_s},
          {"start_age_s", plan.start_age_s},
          {"clock", "restarts at 0; start_age_s is the sensor's age at t = 0"},
          {"heating", heating_json(plan.heating)},
          {"micrometer", micrometer_json(plan.micrometer)},
          {"noise_v", plan.noise_v},
          {"thermocouple_noise_c", plan.thermocouple_noise_c},
          {"thermocouple_resolution_c", plan.thermocouple_resolution_c},
          {"noise_seed", plan.noise_seed}};
}

}  // namespace flange::alt_reality
