// SPDX-License-Identifier: MIT
// An effect of the alternative reality: a departure of its bench from the ideal sensor, written
// from its own formula. It hooks into the places of the chain it acts on; the session renders
// the voltage channel and the temperature channel as two passes over their own sampling
// instants, each with fresh effect instances (so stateful filters start afresh per pass).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "alt_session_plan.h"

namespace flange::alt_reality {

// One instant of one channel as it passes the chain.
struct AltSample {
  double t_s = 0.0;             // session clock at this channel's sampling instant
  double age_s = 0.0;           // the sensor's age at that instant
  double clearance_mm = 0.0;    // what the coil sees (the micrometer's disk plus mount motion)
  double ambient_c = 0.0;       // around sensor and disk
  double coil_c = 0.0;          // the sensing coil (voltage channel)
  double thermocouple_c = 0.0;  // the temperature reading (temperature channel)
  double voltage_v = 0.0;
};

class AltEffect {
 public:
  virtual ~AltEffect() = default;
  virtual void mount(AltSample& /*sample*/) {}                // clearance_mm
  virtual void coil_temperature(AltSample& /*sample*/) {}     // coil_c, voltage channel
  virtual void reading_temperature(AltSample& /*sample*/) {}  // thermocouple_c
  virtual void characteristic(AltSample& /*sample*/) {}       // voltage_v, at the sensor
  virtual void cable(AltSample& /*sample*/) {}                // voltage_v, after the noise
  virtual void converter(AltSample& /*sample*/) {}            // voltage_v, the DAQ
  // How long before `t_s` the voltage channel samples (a skewed channel), s.
  virtual double voltage_delay_s(double /*t_s*/) const { return 0.0; }
};

using AltParams = std::map<std::string, double>;

// One drawn effect: its class, its shape and every parameter (the truth the sidecar records).
struct AltEffectDraw {
  std::string class_name;
  std::string shape;
  AltParams params;
  // The parameter the effect is linear in ("amplitude_v", ...), scaled so that the effect has
  // the drawn size; "" when the shape has none (its size is drawn from physical ranges).
  std::string amplitude_key;
};

// What an effect may read of the session it is built for.
struct SessionView {
  const SessionPlan* plan = nullptr;
};

}  // namespace flange::alt_reality
