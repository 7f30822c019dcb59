// SPDX-License-Identifier: MIT
// temp_offset_drift: an output offset proportional to the coil's temperature rise above a
// reference, beyond what the calibration captured (thesis 4.2 measures it as |V - V_R| against
// the 20 degC reference, eq. 4.1).
#include "effects.h"

namespace flange::sim {
namespace {

class TempOffsetDrift final : public Effect {
 public:
  explicit TempOffsetDrift(const ParamValues& p)
      : offset_v_per_c_(p.at("offset_v_per_c")), reference_c_(p.at("reference_c")) {}

  void apply(ChainSample& sample) override {
    sample.voltage_v += offset_v_per_c_ * (sample.coil_c - reference_c_);
  }

 private:
  double offset_v_per_c_;
  double reference_c_;
};

}  // namespace

EffectSpec temp_offset_drift_effect() {
  EffectSpec spec;
  spec.name = "temp_offset_drift";
  spec.summary = "output offset grows linearly with coil temperature";
  spec.stage = ChainStage::kSensor;
  spec.params = {
      {"offset_v_per_c", -2e-3, -0.05, 0.05, "V/degC", "offset per degree above the reference"},
      {"reference_c", 20.0, -40.0, 150.0, "degC", "temperature of zero offset (thesis: 20 degC)"},
  };
  spec.make = [](const ParamValues& p, const EffectContext&) {
    return std::make_unique<TempOffsetDrift>(p);
  };
  return spec;
}

}  // namespace flange::sim
