// SPDX-License-Identifier: MIT
// range_compression: soft saturation that tightens with temperature. Thesis 4.1: at 79-98 degC,
// from about 8.5 mm on, the output voltages of different clearances lie very close ("effects
// of saturation"; the sensing range shrinks as temperature rises). Above a knee that falls
// linearly with coil temperature the output bends over a tanh towards knee + headroom_v.
#include <algorithm>
#include <cmath>

#include "effects.h"

namespace flange::sim {
namespace {

class RangeCompression final : public Effect {
 public:
  RangeCompression(const ParamValues& p, const EffectContext& context)
      : onset_c_(p.at("onset_c")),
        knee_drop_v_per_c_(p.at("knee_drop_v_per_c")),
        headroom_v_(p.at("headroom_v")),
        v_max_v_(context.v_max_v) {}

  void apply(ChainSample& sample) override {
    const double knee_v = v_max_v_ - knee_drop_v_per_c_ * std::max(0.0, sample.coil_c - onset_c_);
    if (sample.voltage_v <= knee_v) return;
    // Slope 1 at the knee, so the characteristic stays smooth where compression starts.
    sample.voltage_v = knee_v + headroom_v_ * std::tanh((sample.voltage_v - knee_v) / headroom_v_);
  }

 private:
  double onset_c_;
  double knee_drop_v_per_c_;
  double headroom_v_;
  double v_max_v_;
};

}  // namespace

EffectSpec range_compression_effect() {
  EffectSpec spec;
  spec.name = "range_compression";
  spec.summary = "soft saturation near full scale whose knee falls as the coil heats";
  spec.stage = ChainStage::kSensor;
  spec.params = {
      {"onset_c", 50.0, -40.0, 150.0, "degC",
       "coil temperature at which the knee leaves full scale"},
      {"knee_drop_v_per_c", 0.035, 0.0, 1.0, "V/degC", "how fast the knee falls above onset_c"},
      {"headroom_v", 0.5, 0.01, 10.0, "V", "the output approaches knee + headroom_v, never beyond"},
  };
  spec.make = [](const ParamValues& p, const EffectContext& context) {
    return std::make_unique<RangeCompression>(p, context);
  };
  return spec;
}

}  // namespace flange::sim
