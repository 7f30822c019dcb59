// SPDX-License-Identifier: MIT
// thermal_lag: the coil and the thermocouple do not share one temperature. One of them follows
// the ambient through a first-order lag (time constant |tau_s|): tau_s > 0, the coil (inside
// the sensor housing) lags while the thermocouple in the air stream reads the ambient;
// tau_s < 0, the thermocouple (e.g. in a sheath) lags while the coil follows the ambient.
#include <cmath>

#include "effects.h"

namespace flange::sim {
namespace {

class ThermalLag final : public Effect {
 public:
  explicit ThermalLag(double tau_s) : tau_s_(tau_s) {}

  void apply(ChainSample& sample) override {
    if (tau_s_ == 0.0) return;
    const double input = sample.ambient_c;
    if (!started_) {
      lagged_c_ = input;  // the record starts in thermal equilibrium
      started_ = true;
    } else {
      // Exact for an input that is linear between samples (first-order hold), so a ramp lags
      // by exactly |tau_s| whatever the sample rate.
      const double tau = std::abs(tau_s_);
      const double dt = sample.t_s - last_t_s_;
      const double decay = std::exp(-dt / tau);
      const double slope = dt > 0.0 ? (input - last_input_c_) / dt : 0.0;
      lagged_c_ = input - tau * slope + decay * (lagged_c_ - last_input_c_ + tau * slope);
    }
    last_t_s_ = sample.t_s;
    last_input_c_ = input;
    if (tau_s_ > 0.0) {
      sample.coil_c = lagged_c_;
    } else {
      sample.thermocouple_c = lagged_c_;
    }
  }

 private:
  double tau_s_;
  bool started_ = false;
  double lagged_c_ = 0.0;
  double last_t_s_ = 0.0;
  double last_input_c_ = 0.0;
};

}  // namespace

EffectSpec thermal_lag_effect() {
  EffectSpec spec;
  spec.name = "thermal_lag";
  spec.summary = "coil and thermocouple temperatures differ by a first-order lag";
  spec.stage = ChainStage::kThermal;
  spec.params = {
      {"tau_s", 60.0, -3600.0, 3600.0, "s",
       "time constant; > 0 the coil lags the thermocouple, < 0 the thermocouple lags the coil"},
  };
  spec.make = [](const ParamValues& p, const EffectContext&) {
    return std::make_unique<ThermalLag>(p.at("tau_s"));
  };
  return spec;
}

}  // namespace flange::sim
