// SPDX-License-Identifier: MIT
// Sensor thermal lag: the coil inside its housing follows the ambient late, so the voltage is
// that of a cooler (or warmer) coil than the thermocouple reads. Shapes:
//   one_tau: coil = lag(ambient, tau_s)
//   two_tau: coil = w lag(ambient, tau_fast_s) + (1 - w) lag(ambient, tau_slow_s) (a housing
//            and a core)
// Both with the zero-order-hold discretisation of first_order_lag.h.
#include <stdexcept>

#include "alt_classes.h"
#include "first_order_lag.h"

namespace flange::alt_reality {
namespace {

class SensorThermalLag final : public AltEffect {
 public:
  explicit SensorThermalLag(const AltEffectDraw& d)
      : two_(d.shape == "two_tau"),
        weight_(two_ ? d.params.at("weight_fast") : 1.0),
        fast_(two_ ? d.params.at("tau_fast_s") : d.params.at("tau_s")),
        slow_(two_ ? d.params.at("tau_slow_s") : 1.0) {}

  void coil_temperature(AltSample& s) override {
    const double fast = fast_.step(s.t_s, s.ambient_c);
    s.coil_c = two_ ? weight_ * fast + (1.0 - weight_) * slow_.step(s.t_s, s.ambient_c) : fast;
  }

 private:
  bool two_;
  double weight_;
  FirstOrderLag fast_, slow_;
};

}  // namespace

AltClass sensor_thermal_lag_class() {
  AltClass c;
  c.name = "sensor_thermal_lag";
  c.shapes = {"one_tau", "two_tau"};
  c.draw = [](const std::string& shape, const DrawContext&, AltRandom& random) {
    AltEffectDraw d{"sensor_thermal_lag", shape, {}, ""};
    if (shape == "one_tau") {
      d.params["tau_s"] = random.uniform(200.0, 1800.0);
    } else if (shape == "two_tau") {
      d.params["weight_fast"] = random.uniform(0.3, 0.7);
      d.params["tau_fast_s"] = random.uniform(40.0, 200.0);
      d.params["tau_slow_s"] = random.uniform(600.0, 2400.0);
    } else {
      throw std::invalid_argument("sensor_thermal_lag: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView&) {
    return std::make_unique<SensorThermalLag>(d);
  };
  return c;
}

}  // namespace flange::alt_reality
