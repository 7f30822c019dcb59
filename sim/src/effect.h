// SPDX-License-Identifier: MIT
// A named, switchable, parameterised deviation of the real sensor chain from the nominal model.
// Each effect declares where in the signal chain it acts, its parameters with defaults and
// valid ranges, and how to build it; docs/sensor_twin.md gives every effect's equation.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "chain_sample.h"
#include "effect_table.h"

namespace flange::sim {

// Stages of the signal chain, in the order a sample passes them. The nominal inversion runs
// between kThermal and kSensor; the sensor's 0-10 V rails clamp after kSensor; white noise is
// added at the start of kWiring.
enum class ChainStage {
  kMount,        // where the coil is relative to the flange
  kThermal,      // coil and thermocouple temperatures
  kSensor,       // the sensor's voltage characteristic
  kWiring,       // pickup on the cable to the DAQ
  kAcquisition,  // the DAQ's sampling and conversion
};

struct ParamSpec {
  std::string key;
  double default_value = 0.0;
  double min = 0.0;  // valid range, inclusive
  double max = 0.0;
  std::string unit;  // as printed after the range, e.g. "V" or "1/degC"
  std::string meaning;
  bool integer = false;
};

// Parameter values by key; after validation every key of the effect is present.
using ParamValues = std::map<std::string, double>;

// What an effect may need from the twin when it is built.
struct EffectContext {
  double v_min_v = 0.0;  // the sensor's output range (the nominal model's)
  double v_max_v = 10.0;
  std::uint64_t seed = 0;                    // this effect's own random stream
  std::shared_ptr<const EffectTable> table;  // the tabulated effect's table (null for the others)
};

class Effect {
 public:
  virtual ~Effect() = default;
  // Called once per sample, in time order.
  virtual void apply(ChainSample& sample) = 0;
  // An effect that only adds voltages set by the sample's time (mains pickup's tones) says how
  // many terms it adds; apply() then adds time_term(0, t), time_term(1, t), ... in that order and
  // does nothing else. A replay that applies it to the same instants many times (a search with
  // it held) keeps the terms rather than evaluating them again, with the same sums. 0: not such
  // an effect.
  virtual int time_terms() const { return 0; }
  virtual double time_term(int /*term*/, double /*t_s*/) const { return 0.0; }
};

struct EffectSpec {
  std::string name;
  std::string summary;
  ChainStage stage = ChainStage::kSensor;
  std::vector<ParamSpec> params;
  // Checks between parameters (e.g. a band's low edge below its high edge): returns "" when
  // the values go together, else one sentence saying what must hold.
  std::function<std::string(const ParamValues&)> check_together;
  std::function<std::unique_ptr<Effect>(const ParamValues&, const EffectContext&)> make;
};

}  // namespace flange::sim
