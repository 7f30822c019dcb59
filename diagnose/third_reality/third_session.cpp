// SPDX-License-Identifier: MIT
#include "third_session.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "third_classes.h"
#include "third_sensor.h"

namespace flange::third_reality {
namespace {

using Chain = std::vector<std::unique_ptr<ThirdEffect>>;

ChannelPass pass_at(const SessionPlan& plan, std::vector<double> instants) {
  ChannelPass pass;
  pass.plan = &plan;
  pass.instant_s = std::move(instants);
  for (double t : pass.instant_s) {
    pass.ambient_c.push_back(plan.heating(t));
    pass.clearance_mm.push_back(plan.micrometer(t));
  }
  return pass;
}

std::vector<double> temperature_channel(const SessionPlan& plan, const Chain& chain,
                                        const std::vector<double>& instants, bool with_noise) {
  const ChannelPass pass = pass_at(plan, instants);
  std::vector<double> temp = pass.ambient_c;
  for (const auto& e : chain) e->read_temperature(pass, temp);
  ThirdRandom noise(plan.noise_seed * 2 + 1);
  const double step = plan.thermocouple_step_c;
  for (double& t : temp) {
    if (with_noise) t += plan.thermocouple_noise_c * noise.normal();
    t = step * std::round(t / step);
  }
  return temp;
}

std::vector<double> voltage_channel(const SessionPlan& plan, const Chain& chain,
                                    const std::vector<double>& instants, bool with_noise) {
  std::vector<double> late = instants;
  for (std::size_t k = 0; k < late.size(); ++k) {
    for (const auto& e : chain) late[k] -= e->lateness_s(instants[k]);
  }
  ChannelPass pass = pass_at(plan, late);
  std::vector<double> moved = pass.clearance_mm;
  for (const auto& e : chain) e->move(pass, moved);
  pass.clearance_mm = moved;
  std::vector<double> v(late.size());
  for (std::size_t k = 0; k < v.size(); ++k) v[k] = nominal_voltage(moved[k], pass.ambient_c[k]);
  for (const auto& e : chain) e->sense(pass, v);
  ThirdRandom noise(plan.noise_seed * 2);
  for (double& x : v) {
    x = std::clamp(x, kRailLowV, kRailHighV);
    if (with_noise) x += plan.noise_v * noise.normal();
  }
  for (const auto& e : chain) e->pick_up(pass, v);
  for (const auto& e : chain) e->convert(v);
  return v;
}

}  // namespace

double six_decimals(double value) { return std::round(value * 1e6) / 1e6; }

ThirdRecording render_session(const SessionPlan& plan, const std::vector<EffectDraw>& effects,
                              bool with_noise) {
  Chain chain;
  for (const EffectDraw& d : effects) chain.push_back(make_third_effect(d, plan));
  const LoggerTimeline rows = logger_timeline(plan.logger, plan.fs_hz, plan.duration_s, with_noise);
  ThirdRecording r;
  r.dropped = rows.dropped;
  r.temp_c = temperature_channel(plan, chain, rows.instant_s, with_noise);
  r.voltage_v = voltage_channel(plan, chain, rows.instant_s, with_noise);
  for (std::size_t k = 0; k < rows.instant_s.size(); ++k) {
    r.t_s.push_back(six_decimals(rows.stamp_s[k]));
    r.clearance_mm.push_back(six_decimals(plan.micrometer(rows.instant_s[k])));
    r.temp_c[k] = six_decimals(r.temp_c[k]);
    r.voltage_v[k] = six_decimals(r.voltage_v[k]);
  }
  return r;
}

std::vector<double> ideal_twin_gap(const ThirdRecording& r) {
  std::vector<double> gap(r.size());
  for (std::size_t k = 0; k < r.size(); ++k) {
    gap[k] = r.voltage_v[k] - nominal_voltage(r.clearance_mm[k], r.temp_c[k]);
  }
  return gap;
}

nlohmann::json session_plan_json(const SessionPlan& plan) {
  return {{"fs_hz", plan.fs_hz},
          {"duration_s", plan.duration_s},
          {"start_age_s", plan.start_age_s},
          {"clock", "restarts at 0; start_age_s is the sensor's age at t = 0"},
          {"heating", heating_plan_json(plan.heating)},
          {"micrometer", micrometer_plan_json(plan.micrometer)},
          {"logger", logger_plan_json(plan.logger)},
          {"noise_v", plan.noise_v},
          {"thermocouple_noise_c", plan.thermocouple_noise_c},
          {"thermocouple_step_c", plan.thermocouple_step_c},
          {"noise_seed", plan.noise_seed}};
}

}  // namespace flange::third_reality
