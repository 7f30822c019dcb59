// SPDX-License-Identifier: MIT
// thermal_lag_volts: a voltage that follows how far the ambient temperature has run ahead of a
// lagged copy of itself, V += A (S T - T), with S a mix of up to three first-order lags (time
// constants tau_k_s, weights weight_k summing to 1) and A volts per degC of its own: a housing or
// a mount that lags in the heat and pulls the output by a scale that is not the coil's dV/dT (the
// coil's own lag, thermal_lag, moves the voltage only by dV/dT). Added in the sensor stage, after
// the sensor's other effects, as the diagnosis's free lag in volts is added to the twin's voltage.
#include <fmt/format.h>

#include <array>
#include <cmath>
#include <vector>

#include "effects.h"
#include "first_order_lag.h"

namespace flange::sim {
namespace {

constexpr std::size_t kPaths = 3;
// How far the weights may sum from 1 (they are written with 17 digits).
constexpr double kWeightSumTolerance = 1e-6;

std::string tau_key(std::size_t k) { return fmt::format("tau_{}_s", k + 1); }
std::string weight_key(std::size_t k) { return fmt::format("weight_{}", k + 1); }

class ThermalLagVolts final : public Effect {
 public:
  explicit ThermalLagVolts(const ParamValues& p) : volts_per_c_(p.at("v_per_c")) {
    for (std::size_t k = 0; k < kPaths; ++k) {
      weights_[k] = p.at(weight_key(k));
      lags_.emplace_back(p.at(tau_key(k)));
    }
  }

  void apply(ChainSample& sample) override {
    double mix = 0.0;
    for (std::size_t k = 0; k < kPaths; ++k) {
      mix += weights_[k] * lags_[k].step(sample.t_s, sample.ambient_c);
    }
    sample.voltage_v += volts_per_c_ * (mix - sample.ambient_c);
  }

 private:
  double volts_per_c_;
  std::array<double, kPaths> weights_{};
  std::vector<FirstOrderLag> lags_;
};

}  // namespace

EffectSpec thermal_lag_volts_effect() {
  EffectSpec spec;
  spec.name = "thermal_lag_volts";
  spec.summary = "a voltage of its own per degC the temperature leads a mix of its lags";
  spec.stage = ChainStage::kSensor;
  spec.params = {
      {"v_per_c", 0.02, -1.0, 1.0, "V/degC",
       "A: volts per degC of the lagged temperature over the ambient"},
  };
  const std::array<double, kPaths> taus = {240.0, 60.0, 960.0};
  for (std::size_t k = 0; k < kPaths; ++k) {
    spec.params.push_back({tau_key(k), taus[k], 1.0, 3600.0, "s",
                           fmt::format("time constant of lag {}", k + 1)});
    spec.params.push_back({weight_key(k), k == 0 ? 1.0 : 0.0, -10.0, 10.0, "",
                           fmt::format("weight of lag {} in the mix (the weights sum to 1)", k + 1)});
  }
  spec.check_together = [](const ParamValues& p) -> std::string {
    double sum = 0.0;
    for (std::size_t k = 0; k < kPaths; ++k) sum += p.at(weight_key(k));
    if (std::abs(sum - 1.0) <= kWeightSumTolerance) return "";
    return fmt::format("weight_1 + weight_2 + weight_3 = {} must be 1 (within {})", sum,
                       kWeightSumTolerance);
  };
  spec.make = [](const ParamValues& p, const EffectContext&) {
    return std::make_unique<ThermalLagVolts>(p);
  };
  return spec;
}

}  // namespace flange::sim
