// SPDX-License-Identifier: MIT
#include "twin_replay.h"

#include <algorithm>
#include <memory>

#include "effect_catalogue.h"

namespace flange::diagnose {
namespace {

constexpr double kSecondsPerDay = 86400.0;

using sim::ChainStage;

ChainStage stage_of(const std::string& name) {
  return sim::effect_catalogue()[static_cast<std::size_t>(sim::catalogue_index(name))].stage;
}

}  // namespace

double interpolate_at(const std::vector<double>& t, const std::vector<double>& values, double t_s) {
  if (t_s <= t.front()) return values.front();
  if (t_s >= t.back()) return values.back();
  const auto upper = std::upper_bound(t.begin(), t.end(), t_s);
  const std::size_t j = static_cast<std::size_t>(upper - t.begin());
  const double w = (t_s - t[j - 1]) / (t[j] - t[j - 1]);
  return values[j - 1] + w * (values[j] - values[j - 1]);
}

std::vector<double> ambient_from_recorded(const RecordingSeries& series,
                                          const std::vector<sim::EffectSettings>& effects) {
  std::vector<double> ambient = series.temp_c;
  const std::size_t n = ambient.size();
  // Undo in reverse chain order: the skew acts after the lag.
  for (const sim::EffectSettings& effect : effects) {
    if (effect.name == "channel_skew" && effect.params.at("skew_s") > 0.0) {
      const double skew_s = effect.params.at("skew_s");
      std::vector<double> advanced(n);
      for (std::size_t i = 0; i < n; ++i) {
        advanced[i] = interpolate_at(series.t_s, ambient, series.t_s[i] + skew_s);
      }
      ambient = std::move(advanced);
    }
  }
  for (const sim::EffectSettings& effect : effects) {
    if (effect.name == "thermal_lag" && effect.params.at("tau_s") < 0.0 && n >= 3) {
      // A first-order lag y' = (x - y) / tau inverts to x = y + tau y'.
      const double tau_s = -effect.params.at("tau_s");
      std::vector<double> lead(n);
      for (std::size_t i = 0; i < n; ++i) {
        const std::size_t lo = i == 0 ? 0 : i - 1, hi = i + 1 == n ? i : i + 1;
        const double slope = (ambient[hi] - ambient[lo]) / (series.t_s[hi] - series.t_s[lo]);
        lead[i] = ambient[i] + tau_s * slope;
      }
      ambient = std::move(lead);
    }
  }
  return ambient;
}

TwinReplay::TwinReplay(const RecordingSeries& series, const sim::PolynomialSensorModel& nominal,
                       double age_offset_s)
    : series_(series), nominal_(nominal), age_offset_s_(age_offset_s) {
  const std::size_t n = series.size();
  nominal_v_.resize(n);
  nominal_clip_.resize(n);
  sensitivity_.resize(n);
  temperature_sensitivity_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const sim::VoltageSolution v = nominal_.voltage_for(series.clearance_mm[i], series.temp_c[i]);
    nominal_v_[i] = v.volts;
    nominal_clip_[i] = v.clip;
    // dd/dV by a central difference; its inverse is the sensitivity.
    const double h = 1e-3;
    const double dd_dv = (nominal_.clearance_mm(v.volts + h, series.temp_c[i]) -
                          nominal_.clearance_mm(v.volts - h, series.temp_c[i])) /
                         (2.0 * h);
    sensitivity_[i] = dd_dv != 0.0 ? 1.0 / dd_dv : 0.0;
    // At a fixed clearance, dV/dT = -(dd/dT) / (dd/dV).
    const double dd_dt = (nominal_.clearance_mm(v.volts, series.temp_c[i] + h) -
                          nominal_.clearance_mm(v.volts, series.temp_c[i] - h)) /
                         (2.0 * h);
    temperature_sensitivity_[i] = v.clip == sim::RailClip::kNone ? -dd_dt * sensitivity_[i] : 0.0;
  }
}

std::vector<double> TwinReplay::voltage(const std::vector<sim::EffectSettings>& effects,
                                        std::uint64_t seed) const {
  // The sensor's age at this series' t_s = 0, for the effects fitted on another session.
  std::vector<sim::EffectSettings> aged = effects;
  for (sim::EffectSettings& effect : aged) {
    if (effect.name == "ageing_drift") {
      effect.params["start_age_days"] += age_offset_s_ / kSecondsPerDay;
    }
  }
  std::vector<const sim::EffectSettings*> ordered;
  for (const sim::EffectSettings& effect : aged) ordered.push_back(&effect);
  std::sort(ordered.begin(), ordered.end(),
            [](const sim::EffectSettings* a, const sim::EffectSettings* b) {
              return sim::catalogue_index(a->name) < sim::catalogue_index(b->name);
            });
  std::vector<std::unique_ptr<sim::Effect>> chain;
  std::vector<ChainStage> stages;
  bool moves_coil = false;
  for (const sim::EffectSettings* effect : ordered) {
    chain.push_back(sim::make_effect(*effect, nominal_.v_min_v(), nominal_.v_max_v(), seed));
    stages.push_back(stage_of(effect->name));
    moves_coil = moves_coil || stages.back() <= ChainStage::kThermal;
  }
  const auto apply = [&](ChainStage stage, sim::ChainSample& sample) {
    for (std::size_t k = 0; k < chain.size(); ++k) {
      if (stages[k] == stage) chain[k]->apply(sample);
    }
  };

  const std::vector<double> ambient = ambient_from_recorded(series_, effects);
  const bool drive_changed = ambient != series_.temp_c;
  moves_coil = moves_coil || drive_changed;
  std::vector<double> out(series_.size());
  for (std::size_t i = 0; i < series_.size(); ++i) {
    sim::ChainSample sample;
    sample.t_s = series_.t_s[i];
    sample.clearance_mm = series_.clearance_mm[i];
    sample.ambient_c = sample.coil_c = sample.thermocouple_c = ambient[i];
    apply(ChainStage::kMount, sample);
    apply(ChainStage::kThermal, sample);
    if (moves_coil) {
      const sim::VoltageSolution v = nominal_.voltage_for(sample.clearance_mm, sample.coil_c);
      sample.voltage_v = v.volts;
      sample.clip = v.clip;
    } else {
      sample.voltage_v = nominal_v_[i];
      sample.clip = nominal_clip_[i];
    }
    apply(ChainStage::kSensor, sample);
    sample.voltage_v = std::clamp(sample.voltage_v, nominal_.v_min_v(), nominal_.v_max_v());
    apply(ChainStage::kWiring, sample);
    apply(ChainStage::kAcquisition, sample);
    out[i] = sample.voltage_v;
  }
  return out;
}

}  // namespace flange::diagnose
