// SPDX-License-Identifier: MIT
// ageing_drift: an output offset that creeps linearly with the sensor's age. Thesis 4.3: "over
// time, the system loses its properties, and needs a sort of calibration"; 5.1: repeatability
// is inconsistent over time. The age at the start of the record lets a run begin aged.
#include "effects.h"

namespace flange::sim {
namespace {

constexpr double kSecondsPerDay = 86400.0;

class AgeingDrift final : public Effect {
 public:
  explicit AgeingDrift(const ParamValues& p)
      : rate_v_per_day_(p.at("rate_v_per_day")), start_age_days_(p.at("start_age_days")) {}

  void apply(ChainSample& sample) override {
    sample.voltage_v += rate_v_per_day_ * (start_age_days_ + sample.t_s / kSecondsPerDay);
  }

 private:
  double rate_v_per_day_;
  double start_age_days_;
};

}  // namespace

EffectSpec ageing_drift_effect() {
  EffectSpec spec;
  spec.name = "ageing_drift";
  spec.summary = "output offset creeping linearly over hours and days";
  spec.stage = ChainStage::kSensor;
  spec.params = {
      {"rate_v_per_day", -0.05, -2.0, 2.0, "V/day", "offset creep rate"},
      {"start_age_days", 0.0, 0.0, 3650.0, "days", "age since calibration at the record's start"},
  };
  spec.make = [](const ParamValues& p, const EffectContext&) {
    return std::make_unique<AgeingDrift>(p);
  };
  return spec;
}

}  // namespace flange::sim
