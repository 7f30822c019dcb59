// SPDX-License-Identifier: MIT
// Temperature-reading lag: the thermocouple reports the ambient late. Shapes:
//   sheathed:  two first-order lags in series (a probe in a sheath), tau_1_s and tau_2_s
//   dead_time: the ambient of delay_s ago through one first-order lag tau_s (a transport delay
//              in the temperature module)
#include <stdexcept>

#include "alt_classes.h"
#include "first_order_lag.h"

namespace flange::alt_reality {
namespace {

class TemperatureReadingLag final : public AltEffect {
 public:
  TemperatureReadingLag(const AltEffectDraw& d, const SessionView& session)
      : dead_time_(d.shape == "dead_time"),
        delay_s_(dead_time_ ? d.params.at("delay_s") : 0.0),
        first_(dead_time_ ? d.params.at("tau_s") : d.params.at("tau_1_s")),
        second_(dead_time_ ? 1.0 : d.params.at("tau_2_s")),
        heating_(session.plan->heating) {}

  void reading_temperature(AltSample& s) override {
    if (dead_time_) {
      s.thermocouple_c = first_.step(s.t_s, ambient_c(heating_, s.t_s - delay_s_));
    } else {
      s.thermocouple_c = second_.step(s.t_s, first_.step(s.t_s, s.ambient_c));
    }
  }

 private:
  bool dead_time_;
  double delay_s_;
  FirstOrderLag first_, second_;
  HeatingProtocol heating_;
};

}  // namespace

AltClass temperature_reading_lag_class() {
  AltClass c;
  c.name = "temperature_reading_lag";
  c.shapes = {"sheathed", "dead_time"};
  c.draw = [](const std::string& shape, const DrawContext&, AltRandom& random) {
    AltEffectDraw d{"temperature_reading_lag", shape, {}, ""};
    if (shape == "sheathed") {
      d.params["tau_1_s"] = random.uniform(30.0, 500.0);
      d.params["tau_2_s"] = random.uniform(30.0, 500.0);
    } else if (shape == "dead_time") {
      d.params["delay_s"] = random.uniform(10.0, 90.0);
      d.params["tau_s"] = random.uniform(30.0, 400.0);
    } else {
      throw std::invalid_argument("temperature_reading_lag: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView& session) {
    return std::make_unique<TemperatureReadingLag>(d, session);
  };
  return c;
}

}  // namespace flange::alt_reality
