// SPDX-License-Identifier: MIT
// The static nonlinearity follows the clearance: V' = V + A f(u), u the clearance's place in the
// fitting session's range, f a random smooth function (monotone or wavy).
#include <memory>

#include "third_classes.h"

namespace flange::third_reality {
namespace {

class ClearanceFollower : public ThirdEffect {
 public:
  explicit ClearanceFollower(const EffectDraw& d)
      : f_(get_smooth_function(d.params, "f")),
        lo_(d.params.at("clearance_lo_mm")),
        hi_(d.params.at("clearance_hi_mm")),
        amplitude_(d.params.at("amplitude_v")) {}
  void sense(const ChannelPass& pass, std::vector<double>& v) const override {
    for (std::size_t k = 0; k < v.size(); ++k) {
      v[k] += amplitude_ * f_(unit_position(pass.clearance_mm[k], lo_, hi_));
    }
  }

 private:
  SmoothFunction f_;
  double lo_, hi_, amplitude_;
};

}  // namespace

ThirdClass static_nonlinearity_class() {
  ThirdClass c;
  c.name = "static_nonlinearity";
  c.shapes = {"monotone", "wavy"};
  c.draw = [](const std::string& shape, const DrawContext& context, ThirdRandom& random) {
    EffectDraw d{"static_nonlinearity", shape, {}, "amplitude_v"};
    put_smooth_function(draw_smooth_function(shape == "monotone", random), "f", d.params);
    d.params["clearance_lo_mm"] = context.clearance_lo_mm;
    d.params["clearance_hi_mm"] = std::max(context.clearance_hi_mm, context.clearance_lo_mm + 1.0);
    d.params["amplitude_v"] = 0.05;
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<ClearanceFollower>(d);
  };
  return c;
}

}  // namespace flange::third_reality
