// SPDX-License-Identifier: MIT
// The twin driven by a recording's own inputs, without its white noise: the deterministic
// "sim" voltage the diagnosis compares with the recorded one. It runs the catalogue's effects
// in the same chain order as sim::SensorTwin::step (a test checks they agree sample for
// sample), but inverts the nominal model only once per sample and reuses that inversion while
// no mount or thermal effect changes what the coil sees: fitting an effect replays thousands
// of times.
#pragma once

#include <vector>

#include "diagnosis.h"
#include "sensor_twin.h"

namespace flange::diagnose {

// Linear interpolation of `values` (sampled at the increasing times `t`) at time `t_s`, held
// constant beyond the ends.
double interpolate_at(const std::vector<double>& t, const std::vector<double>& values, double t_s);

// The twin's ambient temperature behind a recorded one: effects that delay the temperature
// channel (channel_skew with skew_s > 0, thermal_lag with tau_s < 0) are undone, so that the
// twin driven by the result records what was recorded. Others leave it as recorded.
std::vector<double> ambient_from_recorded(const RecordingSeries& series,
                                          const std::vector<sim::EffectSettings>& effects);

class TwinReplay {
 public:
  // `series` must outlive the replay; `nominal` is the twin's nominal model. `age_offset_s`: how
  // much older the sensor is at the series' t_s = 0 than at the t_s = 0 of the session its
  // effects were fitted on; effects of the sensor's age (ageing_drift) are replayed that much
  // later. The other effects depend on the time only through its differences.
  TwinReplay(const RecordingSeries& series, const sim::PolynomialSensorModel& nominal,
             double age_offset_s = 0.0);

  // The voltage the twin with `effects` (noise off) records for every sample. `seed` seeds the
  // random effects (vibration's tone phases), as the twin's seed does.
  std::vector<double> voltage(const std::vector<sim::EffectSettings>& effects,
                              std::uint64_t seed = 0) const;

  // The nominal model's voltage for every sample (no effect, no noise).
  const std::vector<double>& nominal_voltage() const { return nominal_v_; }
  // dV/dd of the nominal model at every sample (V/mm): how clearance motion shows in volts.
  const std::vector<double>& sensitivity_v_per_mm() const { return sensitivity_; }
  // dV/dT of the nominal model at every sample's clearance (V/degC): how a temperature the coil
  // sees other than the recorded one shows in volts (the free lag family, free_shape_fit.h).
  const std::vector<double>& temperature_sensitivity_v_per_c() const {
    return temperature_sensitivity_;
  }
  const std::vector<double>& times() const { return series_.t_s; }
  double age_offset_s() const { return age_offset_s_; }
  double v_min_v() const { return nominal_.v_min_v(); }

 private:
  const RecordingSeries& series_;
  sim::PolynomialSensorModel nominal_;
  double age_offset_s_;
  std::vector<double> nominal_v_;
  std::vector<sim::RailClip> nominal_clip_;
  std::vector<double> sensitivity_;
  std::vector<double> temperature_sensitivity_;
};

}  // namespace flange::diagnose
