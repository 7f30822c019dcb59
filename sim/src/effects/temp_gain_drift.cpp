// SPDX-License-Identifier: MIT
// temp_gain_drift: the sensor's gain changes with coil temperature beyond what the calibration
// captured. Thesis 4.1: the output voltage drops as temperature rises (the ferrite coil's
// resistance grows), most at large clearances, so the default coefficient is negative.
#include "effects.h"

namespace flange::sim {
namespace {

class TempGainDrift final : public Effect {
 public:
  TempGainDrift(const ParamValues& p, const EffectContext& context)
      : gain_per_c_(p.at("gain_per_c")),
        reference_c_(p.at("reference_c")),
        v_min_v_(context.v_min_v) {}

  void apply(ChainSample& sample) override {
    const double gain = 1.0 + gain_per_c_ * (sample.coil_c - reference_c_);
    sample.voltage_v = v_min_v_ + (sample.voltage_v - v_min_v_) * gain;
  }

 private:
  double gain_per_c_;
  double reference_c_;
  double v_min_v_;
};

}  // namespace

EffectSpec temp_gain_drift_effect() {
  EffectSpec spec;
  spec.name = "temp_gain_drift";
  spec.summary = "output gain changes linearly with coil temperature";
  spec.stage = ChainStage::kSensor;
  spec.params = {
      {"gain_per_c", -5e-4, -0.01, 0.01, "1/degC", "relative gain change per degree"},
      {"reference_c", 20.0, -40.0, 150.0, "degC", "temperature of unit gain (thesis: 20 degC)"},
  };
  spec.make = [](const ParamValues& p, const EffectContext& context) {
    return std::make_unique<TempGainDrift>(p, context);
  };
  return spec;
}

}  // namespace flange::sim
