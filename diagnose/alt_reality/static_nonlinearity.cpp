// SPDX-License-Identifier: MIT
// Static nonlinearity: the characteristic departs from the calibration as a function of the
// voltage or of the clearance alone. Shapes:
//   cubic_voltage:       dV = A u^3, u = (V - centre_v) / 5 V (not zero at the ends)
//   exponential_voltage: dV = A (exp(V / lambda_v) - 1) / (exp(10 V / lambda_v) - 1)
//   clearance_ripple:    dV = A sin(2 pi d / period_mm + phase) (an inhomogeneous target)
// (the twin's is a bow plus an S-curve that vanish at both ends of the range).
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

class StaticNonlinearity final : public AltEffect {
 public:
  explicit StaticNonlinearity(const AltEffectDraw& d) : shape_(d.shape), p_(d.params) {}

  void characteristic(AltSample& s) override {
    const double a = p_.at("amplitude_v");
    if (shape_ == "cubic_voltage") {
      const double u = (s.voltage_v - p_.at("centre_v")) / 5.0;
      s.voltage_v += a * u * u * u;
    } else if (shape_ == "exponential_voltage") {
      const double lambda = p_.at("lambda_v");
      s.voltage_v += a * std::expm1(s.voltage_v / lambda) / std::expm1(10.0 / lambda);
    } else {
      s.voltage_v += a * std::sin(2.0 * std::numbers::pi * s.clearance_mm / p_.at("period_mm") +
                                  p_.at("phase_rad"));
    }
  }

 private:
  std::string shape_;
  AltParams p_;
};

}  // namespace

AltClass static_nonlinearity_class() {
  AltClass c;
  c.name = "static_nonlinearity";
  c.shapes = {"cubic_voltage", "exponential_voltage", "clearance_ripple"};
  c.draw = [](const std::string& shape, const DrawContext&, AltRandom& random) {
    AltEffectDraw d{"static_nonlinearity", shape, {}, "amplitude_v"};
    d.params["amplitude_v"] = random.sign();
    if (shape == "cubic_voltage") {
      d.params["centre_v"] = random.uniform(4.0, 6.0);
    } else if (shape == "exponential_voltage") {
      d.params["lambda_v"] = random.uniform(1.5, 4.0);
    } else if (shape == "clearance_ripple") {
      d.params["period_mm"] = random.uniform(2.0, 5.0);
      d.params["phase_rad"] = random.uniform(-std::numbers::pi, std::numbers::pi);
    } else {
      throw std::invalid_argument("static_nonlinearity: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView&) {
    return std::make_unique<StaticNonlinearity>(d);
  };
  return c;
}

}  // namespace flange::alt_reality
