// SPDX-License-Identifier: MIT
// Classes that follow the temperature: an offset A f(u) and a gain about a pivot,
// V' = P + (V - P)(1 + A f(u)), with u the temperature's place in the fitting session's range
// and f a random smooth function (monotone or wavy).
#include <memory>

#include "third_classes.h"

namespace flange::third_reality {
namespace {

class TemperatureFollower : public ThirdEffect {
 public:
  TemperatureFollower(const EffectDraw& d, bool gain)
      : f_(get_smooth_function(d.params, "f")),
        lo_(d.params.at("temp_lo_c")),
        hi_(d.params.at("temp_hi_c")),
        amplitude_(d.params.at(gain ? "gain_amplitude" : "amplitude_v")),
        pivot_(gain ? d.params.at("pivot_v") : 0.0),
        gain_(gain) {}
  void sense(const ChannelPass& pass, std::vector<double>& v) const override {
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double shape = amplitude_ * f_(unit_position(pass.ambient_c[k], lo_, hi_));
      v[k] = gain_ ? pivot_ + (v[k] - pivot_) * (1.0 + shape) : v[k] + shape;
    }
  }

 private:
  SmoothFunction f_;
  double lo_, hi_, amplitude_, pivot_;
  bool gain_;
};

EffectDraw draw_follower(const std::string& name, const std::string& shape, bool gain,
                         const DrawContext& context, ThirdRandom& random) {
  EffectDraw d{name, shape, {}, gain ? "gain_amplitude" : "amplitude_v"};
  put_smooth_function(draw_smooth_function(shape == "monotone", random), "f", d.params);
  d.params["temp_lo_c"] = context.temp_lo_c;
  d.params["temp_hi_c"] = std::max(context.temp_hi_c, context.temp_lo_c + 5.0);
  d.params[d.amplitude_key] = gain ? 0.01 : 0.05;
  if (gain) d.params["pivot_v"] = random.uniform(0.0, 6.0);
  return d;
}

}  // namespace

ThirdClass temperature_offset_class() {
  ThirdClass c;
  c.name = "temperature_offset";
  c.shapes = {"monotone", "wavy"};
  c.draw = [](const std::string& shape, const DrawContext& context, ThirdRandom& random) {
    return draw_follower("temperature_offset", shape, false, context, random);
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<TemperatureFollower>(d, false);
  };
  return c;
}

ThirdClass temperature_gain_class() {
  ThirdClass c;
  c.name = "temperature_gain";
  c.shapes = {"monotone", "wavy"};
  c.draw = [](const std::string& shape, const DrawContext& context, ThirdRandom& random) {
    return draw_follower("temperature_gain", shape, true, context, random);
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<TemperatureFollower>(d, true);
  };
  return c;
}

}  // namespace flange::third_reality
