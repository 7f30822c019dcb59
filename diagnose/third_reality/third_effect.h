// SPDX-License-Identifier: MIT
// An effect of the third reality: a departure of its bench from the ideal sensor, defined by what
// it follows (a temperature, its rate of change through a lag kernel, the clearance, the voltage
// level, the sensor's age, the clock, a frequency band), its shape drawn per pair. A session
// renders each channel as one pass over its sampling instants; an effect hooks into the places
// of the chain it acts on, a whole channel at a time (a lag needs the series).
#pragma once

#include <string>
#include <vector>

#include "smooth_function.h"
#include "third_session_plan.h"

namespace flange::third_reality {

// One channel's pass: the instants it samples at and what the bench does there.
struct ChannelPass {
  const SessionPlan* plan = nullptr;
  std::vector<double> instant_s;     // session clock at each sampling instant
  std::vector<double> ambient_c;     // the temperature around sensor and disk
  std::vector<double> clearance_mm;  // what the coil sees (the micrometer plus mount motion)
  double age_s(std::size_t k) const { return plan->start_age_s + instant_s[k]; }
};

class ThirdEffect {
 public:
  virtual ~ThirdEffect() = default;
  // How late the voltage channel samples at `instant_s`, s (a skewed channel).
  virtual double lateness_s(double /*instant_s*/) const { return 0.0; }
  virtual void move(const ChannelPass& /*pass*/, std::vector<double>& /*clearance_mm*/) const {}
  // At the sensor, before the noise.
  virtual void sense(const ChannelPass& /*pass*/, std::vector<double>& /*voltage_v*/) const {}
  // On the cable, after the noise.
  virtual void pick_up(const ChannelPass& /*pass*/, std::vector<double>& /*voltage_v*/) const {}
  // The data acquisition's converter.
  virtual void convert(std::vector<double>& /*voltage_v*/) const {}
  // The temperature channel (before its noise and display step).
  virtual void read_temperature(const ChannelPass& /*pass*/,
                                std::vector<double>& /*temp_c*/) const {}
};

// One drawn effect: class, shape and every parameter (the truth the sidecar records).
struct EffectDraw {
  std::string class_name;
  std::string shape;
  Params params;
  // The parameter that sets its size ("amplitude_v", "late_s", ...), scaled until the effect has
  // the drawn size; "" for an effect sized by setting the noise (a lagging reading, a converter).
  std::string amplitude_key;
};

}  // namespace flange::third_reality
