// SPDX-License-Identifier: MIT
// thermal_lag: the coil and the thermocouple do not share one temperature. One of them follows
// the ambient through a first-order lag (time constant |tau_s|): tau_s > 0, the coil (inside
// the sensor housing) lags while the thermocouple in the air stream reads the ambient;
// tau_s < 0, the thermocouple (e.g. in a sheath) lags while the coil follows the ambient.
#include <cmath>

#include "effects.h"
#include "first_order_lag.h"

namespace flange::sim {
namespace {

class ThermalLag final : public Effect {
 public:
  explicit ThermalLag(double tau_s) : tau_s_(tau_s), lag_(std::abs(tau_s)) {}

  void apply(ChainSample& sample) override {
    if (tau_s_ == 0.0) return;
    const double lagged_c = lag_.step(sample.t_s, sample.ambient_c);
    if (tau_s_ > 0.0) {
      sample.coil_c = lagged_c;
    } else {
      sample.thermocouple_c = lagged_c;
    }
  }

 private:
  double tau_s_;
  FirstOrderLag lag_;
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
