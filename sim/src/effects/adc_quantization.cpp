// SPDX-License-Identifier: MIT
// adc_quantization: the DAQ's converter rounds the voltage to its LSB grid and clamps it to its
// input range; threshold_lsb moves the code boundaries (0.5: a truncating converter). Defaults are
// the thesis's NI USB-6221: 16 bits on the +-10 V range (LSB = 20 V / 2^16 = 0.305 mV). The
// thermocouple channel is left unquantised.
#include <algorithm>
#include <cmath>

#include "effects.h"

namespace flange::sim {
namespace {

class AdcQuantization final : public Effect {
 public:
  explicit AdcQuantization(const ParamValues& p)
      : v_min_v_(p.at("v_min")),
        lsb_v_((p.at("v_max") - p.at("v_min")) / std::ldexp(1.0, static_cast<int>(p.at("bits")))),
        top_code_(std::ldexp(1.0, static_cast<int>(p.at("bits"))) - 1.0),
        threshold_lsb_(p.at("threshold_lsb")) {}

  void apply(ChainSample& sample) override {
    const double code = std::clamp(
        std::round((sample.voltage_v - v_min_v_) / lsb_v_ - threshold_lsb_), 0.0, top_code_);
    sample.voltage_v = v_min_v_ + code * lsb_v_;
  }

 private:
  double v_min_v_;
  double lsb_v_;
  double top_code_;
  double threshold_lsb_;
};

}  // namespace

EffectSpec adc_quantization_effect() {
  EffectSpec spec;
  spec.name = "adc_quantization";
  spec.summary = "voltage rounded to the converter's LSB grid and clamped to its range";
  spec.stage = ChainStage::kAcquisition;
  spec.params = {
      {"bits", 16.0, 4.0, 24.0, "", "converter resolution", true},
      {"v_min", -10.0, -100.0, 100.0, "V", "bottom of the input range (code 0)"},
      {"v_max", 10.0, -100.0, 100.0, "V", "top of the input range (code 2^bits is v_max)"},
      {"threshold_lsb", 0.0, -0.5, 0.5, "LSB",
       "where the code boundaries sit against rounding's: 0 rounds, 0.5 truncates"},
  };
  spec.check_together = [](const ParamValues& p) -> std::string {
    return p.at("v_min") < p.at("v_max") ? "" : "v_min must be below v_max";
  };
  spec.make = [](const ParamValues& p, const EffectContext&) {
    return std::make_unique<AdcQuantization>(p);
  };
  return spec;
}

}  // namespace flange::sim
