// SPDX-License-Identifier: MIT
// nonlinearity: the real characteristic departs from the calibration polynomial in shape, as an
// integral-nonlinearity error that vanishes at both ends of the output range: an even bow
// (peak bow_v at mid-scale) and an odd S-curve (-s_curve_v at 21 %, +s_curve_v at 79 % of scale).
#include <cmath>

#include "effects.h"

namespace flange::sim {
namespace {

class Nonlinearity final : public Effect {
 public:
  Nonlinearity(const ParamValues& p, const EffectContext& context)
      : bow_v_(p.at("bow_v")),
        s_curve_v_(p.at("s_curve_v")),
        v_min_v_(context.v_min_v),
        span_v_(context.v_max_v - context.v_min_v) {}

  void apply(ChainSample& sample) override {
    const double u = (sample.voltage_v - v_min_v_) / span_v_;  // 0 to 1 over the range
    if (u <= 0.0 || u >= 1.0) return;
    const double x = 2.0 * u - 1.0;
    // x (1 - x^2) peaks at 2 / (3 sqrt 3); the factor scales that peak to 1.
    const double s_shape = 1.5 * std::sqrt(3.0) * x * (1.0 - x * x);
    sample.voltage_v += bow_v_ * 4.0 * u * (1.0 - u) + s_curve_v_ * s_shape;
  }

 private:
  double bow_v_;
  double s_curve_v_;
  double v_min_v_;
  double span_v_;
};

}  // namespace

EffectSpec nonlinearity_effect() {
  EffectSpec spec;
  spec.name = "nonlinearity";
  spec.summary = "shape error of the characteristic: a bow and an S-curve, zero at both ends";
  spec.stage = ChainStage::kSensor;
  spec.params = {
      {"bow_v", 0.05, -1.0, 1.0, "V", "even error, its peak at mid-scale"},
      {"s_curve_v", 0.03, -1.0, 1.0, "V",
       "odd error: -s_curve_v at 21 % of scale, +s_curve_v at 79 %"},
  };
  spec.make = [](const ParamValues& p, const EffectContext& context) {
    return std::make_unique<Nonlinearity>(p, context);
  };
  return spec;
}

}  // namespace flange::sim
