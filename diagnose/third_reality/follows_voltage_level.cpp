// SPDX-License-Identifier: MIT
// Classes that follow the voltage level: a range compression above a knee (fixed, or falling as
// the temperature rises), V' = V - A x^2 (1.25 + 0.5 f(x)) / 1.75 with x the voltage's place
// between the knee and the rail and f a random smooth function; and the converter, 4-10 bits on
// one of three ranges, rounding or truncating.
#include <algorithm>
#include <cmath>
#include <memory>

#include "third_classes.h"
#include "third_sensor.h"

namespace flange::third_reality {
namespace {

class Compression : public ThirdEffect {
 public:
  explicit Compression(const EffectDraw& d)
      : f_(get_smooth_function(d.params, "f")),
        knee_v_(d.params.at("knee_v")),
        knee_fall_(d.params.at("knee_fall_v_per_c")),
        temp_lo_c_(d.params.at("temp_lo_c")),
        amplitude_(d.params.at("amplitude_v")) {}
  void sense(const ChannelPass& pass, std::vector<double>& v) const override {
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double knee = knee_v_ - knee_fall_ * (pass.ambient_c[k] - temp_lo_c_);
      if (v[k] <= knee) continue;
      const double x = (v[k] - knee) / (kRailHighV - knee);
      v[k] -= amplitude_ * x * x * (1.25 + 0.5 * f_(x)) / 1.75;
    }
  }

 private:
  SmoothFunction f_;
  double knee_v_, knee_fall_, temp_lo_c_, amplitude_;
};

class Converter : public ThirdEffect {
 public:
  explicit Converter(const EffectDraw& d)
      : lo_v_(d.params.at("range_lo_v")),
        hi_v_(d.params.at("range_hi_v")),
        lsb_v_((hi_v_ - lo_v_) / std::ldexp(1.0, static_cast<int>(d.params.at("bits")))),
        truncating_(d.shape == "truncating") {}
  void convert(std::vector<double>& v) const override {
    const double top = (hi_v_ - lo_v_) / lsb_v_ - 1.0;
    for (double& x : v) {
      const double code = (x - lo_v_) / lsb_v_;
      x = lo_v_ + lsb_v_ * std::clamp(truncating_ ? std::floor(code) : std::round(code), 0.0, top);
    }
  }

 private:
  double lo_v_, hi_v_, lsb_v_;
  bool truncating_;
};

}  // namespace

ThirdClass range_compression_class() {
  ThirdClass c;
  c.name = "range_compression";
  c.shapes = {"fixed_knee", "falling_knee"};
  c.draw = [](const std::string& shape, const DrawContext& context, ThirdRandom& random) {
    EffectDraw d{"range_compression", shape, {}, "amplitude_v"};
    put_smooth_function(draw_smooth_function(random.chance(0.5), random), "f", d.params);
    d.params["knee_v"] = random.uniform(context.voltage_median_v, context.voltage_high_v);
    d.params["knee_fall_v_per_c"] = shape == "falling_knee" ? random.uniform(0.005, 0.03) : 0.0;
    d.params["temp_lo_c"] = context.temp_lo_c;
    d.params["amplitude_v"] = 0.2;
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<Compression>(d);
  };
  return c;
}

ThirdClass quantisation_class() {
  ThirdClass c;
  c.name = "quantisation";
  c.shapes = {"rounding", "truncating"};
  c.bias_type = false;
  c.sets_noise = true;
  c.draw = [](const std::string& shape, const DrawContext&, ThirdRandom& random) {
    EffectDraw d{"quantisation", shape, {}, ""};
    constexpr double kRanges[3][2] = {{0.0, 10.24}, {0.0, 12.0}, {-10.24, 10.24}};
    const int range = random.below(3);
    d.params["range_lo_v"] = kRanges[range][0];
    d.params["range_hi_v"] = kRanges[range][1];
    d.params["bits"] = static_cast<double>(4 + random.below(7));
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<Converter>(d);
  };
  return c;
}

}  // namespace flange::third_reality
