// SPDX-License-Identifier: MIT
// Quantisation: a coarse converter (4 to 10 bits) on ranges that are none of the twin's four.
// Shapes:
//   rounding:              code = round((V - v_lo) / LSB) on [v_lo, v_hi] = 0-10.24 V, 0-12 V
//                          or +-10.24 V; the recording holds v_lo + code LSB
//   truncating_calibrated: a -5..5 V converter behind a -5 V level shift that truncates
//                          (code = floor), and the DAQ software's calibration
//                          recorded = gain_cal (v_lo + code LSB) + 5 V + offset_cal, which puts
//                          the grid at any LSB and origin
// Codes are clamped to the converter's range.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

class Quantisation final : public AltEffect {
 public:
  explicit Quantisation(const AltEffectDraw& d)
      : truncating_(d.shape == "truncating_calibrated"),
        v_lo_(d.params.at("v_lo")),
        lsb_v_((d.params.at("v_hi") - v_lo_) /
               std::ldexp(1.0, static_cast<int>(d.params.at("bits")))),
        top_code_(std::ldexp(1.0, static_cast<int>(d.params.at("bits"))) - 1.0),
        gain_cal_(truncating_ ? d.params.at("gain_cal") : 1.0),
        offset_cal_v_(truncating_ ? d.params.at("offset_cal_v") : 0.0) {}

  void converter(AltSample& s) override {
    const double input = truncating_ ? s.voltage_v - 5.0 : s.voltage_v;
    const double position = (input - v_lo_) / lsb_v_;
    const double code =
        std::clamp(truncating_ ? std::floor(position) : std::round(position), 0.0, top_code_);
    const double converted = v_lo_ + code * lsb_v_;
    s.voltage_v = truncating_ ? gain_cal_ * converted + 5.0 + offset_cal_v_ : converted;
  }

 private:
  bool truncating_;
  double v_lo_, lsb_v_, top_code_, gain_cal_, offset_cal_v_;
};

}  // namespace

AltClass quantisation_class() {
  AltClass c;
  c.name = "quantisation";
  c.shapes = {"rounding", "truncating_calibrated"};
  c.bias_type = false;
  c.draw = [](const std::string& shape, const DrawContext&, AltRandom& random) {
    AltEffectDraw d{"quantisation", shape, {}, ""};
    d.params["bits"] = 4 + random.index(7);
    if (shape == "rounding") {
      constexpr double kRanges[3][2] = {{0.0, 10.24}, {0.0, 12.0}, {-10.24, 10.24}};
      const auto& range = kRanges[random.index(3)];
      d.params["v_lo"] = range[0];
      d.params["v_hi"] = range[1];
    } else if (shape == "truncating_calibrated") {
      d.params["v_lo"] = -5.0;
      d.params["v_hi"] = 5.0;
      d.params["gain_cal"] = random.uniform(0.99, 1.01);
      d.params["offset_cal_v"] = random.uniform(-0.05, 0.05);
    } else {
      throw std::invalid_argument("quantisation: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView&) {
    return std::make_unique<Quantisation>(d);
  };
  return c;
}

}  // namespace flange::alt_reality
