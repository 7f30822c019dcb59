// SPDX-License-Identifier: MIT
// Range compression: the top of the output range saturates, more as the coil heats. Shapes:
//   tanh_exponential_law:   knee(T) = K0 - D (1 - exp(-max(0, T - T_on) / theta_c)); above it
//                           V' = knee + h tanh((V - knee) / h)
//   linear_knee_quadratic_law: knee(T) = K0 - D (max(0, T - T_on) / (90 degC - T_on))^2; above
//                           it V' = knee + slope (V - knee)
// (the twin's knee starts at 10 V and falls linearly with temperature, with a tanh above it).
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

class RangeCompression final : public AltEffect {
 public:
  explicit RangeCompression(const AltEffectDraw& d)
      : linear_knee_(d.shape == "linear_knee_quadratic_law"),
        knee0_v_(d.params.at("knee0_v")),
        drop_v_(d.params.at("drop_v")),
        onset_c_(d.params.at("onset_c")),
        shape_value_(linear_knee_ ? d.params.at("slope") : d.params.at("headroom_v")),
        theta_c_(linear_knee_ ? 0.0 : d.params.at("theta_c")) {}

  void characteristic(AltSample& s) override {
    const double above = std::max(0.0, s.coil_c - onset_c_);
    double knee_v = 0.0;
    if (linear_knee_) {
      const double r = above / std::max(90.0 - onset_c_, 1.0);
      knee_v = knee0_v_ - drop_v_ * r * r;
    } else {
      knee_v = knee0_v_ - drop_v_ * (1.0 - std::exp(-above / theta_c_));
    }
    if (s.voltage_v <= knee_v) return;
    const double over = s.voltage_v - knee_v;
    s.voltage_v = linear_knee_ ? knee_v + shape_value_ * over
                               : knee_v + shape_value_ * std::tanh(over / shape_value_);
  }

 private:
  bool linear_knee_;
  double knee0_v_, drop_v_, onset_c_, shape_value_, theta_c_;
};

}  // namespace

AltClass range_compression_class() {
  AltClass c;
  c.name = "range_compression";
  c.shapes = {"tanh_exponential_law", "linear_knee_quadratic_law"};
  c.draw = [](const std::string& shape, const DrawContext&, AltRandom& random) {
    AltEffectDraw d{"range_compression", shape, {}, ""};
    d.params["knee0_v"] = random.uniform(8.6, 9.8);
    d.params["drop_v"] = random.uniform(1.0, 3.5);
    d.params["onset_c"] = random.uniform(25.0, 50.0);
    if (shape == "tanh_exponential_law") {
      d.params["theta_c"] = random.uniform(15.0, 40.0);
      d.params["headroom_v"] = random.uniform(0.3, 1.2);
    } else if (shape == "linear_knee_quadratic_law") {
      d.params["slope"] = random.uniform(0.2, 0.6);
    } else {
      throw std::invalid_argument("range_compression: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView&) {
    return std::make_unique<RangeCompression>(d);
  };
  return c;
}

}  // namespace flange::alt_reality
