// SPDX-License-Identifier: MIT
// Classes that follow time: the ageing follows the sensor's age, V' = V + A f(u) with u the age's
// place (linear or logarithmic) between the fitting session's start and the held-out session's
// end and f a random monotone smooth function; the channel skew follows the clock, the voltage
// channel sampled late by L (0.3 + 0.7 (f(t / duration) + 1) / 2), f constant or a random
// smooth function of the session clock.
#include <cmath>
#include <memory>

#include "third_classes.h"

namespace flange::third_reality {
namespace {

class Ageing : public ThirdEffect {
 public:
  explicit Ageing(const EffectDraw& d)
      : f_(get_smooth_function(d.params, "f")),
        lo_(d.params.at("age_lo_s")),
        hi_(d.params.at("age_hi_s")),
        amplitude_(d.params.at("amplitude_v")),
        logarithmic_(d.shape == "log_age") {}
  void sense(const ChannelPass& pass, std::vector<double>& v) const override {
    for (std::size_t k = 0; k < v.size(); ++k) {
      const double age = pass.age_s(k);
      const double u = logarithmic_ ? unit_position(std::log(age), std::log(lo_), std::log(hi_))
                                    : unit_position(age, lo_, hi_);
      v[k] += amplitude_ * f_(u);
    }
  }

 private:
  SmoothFunction f_;
  double lo_, hi_, amplitude_;
  bool logarithmic_;
};

class LateChannel : public ThirdEffect {
 public:
  LateChannel(const EffectDraw& d, double duration_s)
      : f_(get_smooth_function(d.params, "f")),
        late_s_(d.params.at("late_s")),
        duration_s_(duration_s),
        constant_(d.shape == "constant") {}
  double lateness_s(double instant_s) const override {
    const double shape = constant_ ? 1.0 : f_(instant_s / duration_s_);
    return late_s_ * (0.3 + 0.35 * (shape + 1.0));
  }

 private:
  SmoothFunction f_;
  double late_s_, duration_s_;
  bool constant_;
};

}  // namespace

ThirdClass ageing_class() {
  ThirdClass c;
  c.name = "ageing";
  c.shapes = {"linear_age", "log_age"};
  c.draw = [](const std::string& shape, const DrawContext& context, ThirdRandom& random) {
    EffectDraw d{"ageing", shape, {}, "amplitude_v"};
    put_smooth_function(draw_smooth_function(true, random), "f", d.params);
    d.params["age_lo_s"] = context.age_lo_s;
    d.params["age_hi_s"] = context.age_hi_s;
    d.params["amplitude_v"] = 0.05;
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<Ageing>(d);
  };
  return c;
}

ThirdClass channel_skew_class() {
  ThirdClass c;
  c.name = "channel_skew";
  c.shapes = {"constant", "wandering"};
  c.draw = [](const std::string& shape, const DrawContext&, ThirdRandom& random) {
    EffectDraw d{"channel_skew", shape, {}, "late_s"};
    put_smooth_function(draw_smooth_function(random.chance(0.5), random), "f", d.params);
    d.params["late_s"] = random.uniform(1.0, 6.0);
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan& plan) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<LateChannel>(d, plan.duration_s);
  };
  return c;
}

}  // namespace flange::third_reality
