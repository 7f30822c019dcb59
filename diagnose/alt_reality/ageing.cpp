// SPDX-License-Identifier: MIT
// Ageing: an output offset that is a function of the sensor's age (its time since calibration,
// which runs on across sessions whose clocks restart at 0). Shapes:
//   log_time: dV = A ln(1 + age / tau_days)
//   step:     dV = A once the age passes step_age_s (a shock; inside the fitting session)
// (the twin's ageing is linear in time).
#include <cmath>
#include <stdexcept>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

constexpr double kSecondsPerDay = 86400.0;

class Ageing final : public AltEffect {
 public:
  explicit Ageing(const AltEffectDraw& d)
      : step_(d.shape == "step"),
        amplitude_v_(d.params.at("amplitude_v")),
        time_s_(step_ ? d.params.at("step_age_s") : d.params.at("tau_days") * kSecondsPerDay) {}

  void characteristic(AltSample& s) override {
    if (step_) {
      s.voltage_v += s.age_s >= time_s_ ? amplitude_v_ : 0.0;
    } else {
      s.voltage_v += amplitude_v_ * std::log1p(s.age_s / time_s_);
    }
  }

 private:
  bool step_;
  double amplitude_v_, time_s_;
};

}  // namespace

AltClass ageing_class() {
  AltClass c;
  c.name = "ageing";
  c.shapes = {"log_time", "step"};
  c.draw = [](const std::string& shape, const DrawContext& context, AltRandom& random) {
    AltEffectDraw d{"ageing", shape, {}, "amplitude_v"};
    d.params["amplitude_v"] = random.sign();
    if (shape == "log_time") {
      d.params["tau_days"] = random.log_uniform(0.02, 2.0);
    } else if (shape == "step") {
      d.params["step_age_s"] =
          context.fit_start_age_s + random.uniform(0.3, 0.7) * context.fit_duration_s;
    } else {
      throw std::invalid_argument("ageing: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView&) { return std::make_unique<Ageing>(d); };
  return c;
}

}  // namespace flange::alt_reality
