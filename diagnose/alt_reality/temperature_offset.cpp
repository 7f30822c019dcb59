// SPDX-License-Identifier: MIT
// Temperature offset: an output offset that depends on the coil temperature. Shapes:
//   quadratic:  dV = A q |q|, q = (T_coil - T_ref) / 80 degC (grows with the square of the rise)
//   saturating: dV = A (1 - exp(-(T_coil - T_ref) / scale_c)) (levels off when hot)
// (the twin's offset is linear in temperature).
#include <cmath>
#include <stdexcept>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

class TemperatureOffset final : public AltEffect {
 public:
  explicit TemperatureOffset(const AltEffectDraw& d)
      : saturating_(d.shape == "saturating"),
        amplitude_v_(d.params.at("amplitude_v")),
        reference_c_(d.params.at("reference_c")),
        scale_c_(saturating_ ? d.params.at("scale_c") : 80.0) {}

  void characteristic(AltSample& s) override {
    const double rise = s.coil_c - reference_c_;
    if (saturating_) {
      s.voltage_v += amplitude_v_ * (1.0 - std::exp(-rise / scale_c_));
    } else {
      const double q = rise / scale_c_;
      s.voltage_v += amplitude_v_ * q * std::abs(q);
    }
  }

 private:
  bool saturating_;
  double amplitude_v_, reference_c_, scale_c_;
};

}  // namespace

AltClass temperature_offset_class() {
  AltClass c;
  c.name = "temperature_offset";
  c.shapes = {"quadratic", "saturating"};
  c.draw = [](const std::string& shape, const DrawContext&, AltRandom& random) {
    AltEffectDraw d{"temperature_offset", shape, {}, "amplitude_v"};
    d.params["amplitude_v"] = random.sign();
    d.params["reference_c"] = random.uniform(15.0, 25.0);
    if (shape == "saturating") {
      d.params["scale_c"] = random.uniform(15.0, 40.0);
    } else if (shape != "quadratic") {
      throw std::invalid_argument("temperature_offset: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView&) {
    return std::make_unique<TemperatureOffset>(d);
  };
  return c;
}

}  // namespace flange::alt_reality
