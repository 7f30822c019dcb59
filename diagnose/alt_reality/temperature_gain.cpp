// SPDX-License-Identifier: MIT
// Temperature gain: the sensor's gain depends on the coil temperature. Shapes:
//   mid_pivot: V' = P + (V - P)(1 + A (T_coil - T_ref) / 80 degC), pivoting about P (4-6 V)
//   quadratic: V' = V (1 + A ((T_coil - T_ref) / 80 degC)^2)
// (the twin's gain is linear in temperature and pivots about 0 V).
#include <stdexcept>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

class TemperatureGain final : public AltEffect {
 public:
  explicit TemperatureGain(const AltEffectDraw& d)
      : quadratic_(d.shape == "quadratic"),
        amplitude_(d.params.at("amplitude")),
        reference_c_(d.params.at("reference_c")),
        pivot_v_(quadratic_ ? 0.0 : d.params.at("pivot_v")) {}

  void characteristic(AltSample& s) override {
    const double q = (s.coil_c - reference_c_) / 80.0;
    const double change = amplitude_ * (quadratic_ ? q * q : q);
    s.voltage_v = pivot_v_ + (s.voltage_v - pivot_v_) * (1.0 + change);
  }

 private:
  bool quadratic_;
  double amplitude_, reference_c_, pivot_v_;
};

}  // namespace

AltClass temperature_gain_class() {
  AltClass c;
  c.name = "temperature_gain";
  c.shapes = {"mid_pivot", "quadratic"};
  c.draw = [](const std::string& shape, const DrawContext&, AltRandom& random) {
    AltEffectDraw d{"temperature_gain", shape, {}, "amplitude"};
    d.params["amplitude"] = random.sign();
    d.params["reference_c"] = random.uniform(15.0, 25.0);
    if (shape == "mid_pivot") {
      d.params["pivot_v"] = random.uniform(4.0, 6.0);
    } else if (shape != "quadratic") {
      throw std::invalid_argument("temperature_gain: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView&) {
    return std::make_unique<TemperatureGain>(d);
  };
  return c;
}

}  // namespace flange::alt_reality
