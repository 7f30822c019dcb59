// SPDX-License-Identifier: MIT
// Channel skew: the voltage channel samples earlier than the time it is stamped with (a second
// DAQ module). The session evaluates the whole voltage chain at the earlier instant, so nothing
// is interpolated between samples. Shapes:
//   constant_delay: the voltage is delay_s old
//   clock_drift:    the voltage module's clock runs slow: delay = delay0_s + drift * t
#include <stdexcept>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

class ChannelSkew final : public AltEffect {
 public:
  explicit ChannelSkew(const AltEffectDraw& d)
      : delay0_s_(d.shape == "clock_drift" ? d.params.at("delay0_s") : d.params.at("delay_s")),
        drift_(d.shape == "clock_drift" ? d.params.at("drift_s_per_s") : 0.0) {}

  double voltage_delay_s(double t_s) const override { return delay0_s_ + drift_ * t_s; }

 private:
  double delay0_s_, drift_;
};

}  // namespace

AltClass channel_skew_class() {
  AltClass c;
  c.name = "channel_skew";
  c.shapes = {"constant_delay", "clock_drift"};
  c.draw = [](const std::string& shape, const DrawContext& context, AltRandom& random) {
    AltEffectDraw d{"channel_skew", shape, {}, ""};
    if (shape == "constant_delay") {
      d.params["delay_s"] = random.uniform(1.0, 8.0);
    } else if (shape == "clock_drift") {
      d.params["delay0_s"] = random.uniform(0.0, 2.0);
      d.params["drift_s_per_s"] =
          (random.uniform(3.0, 10.0) - d.params["delay0_s"]) / context.fit_duration_s;
    } else {
      throw std::invalid_argument("channel_skew: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView&) {
    return std::make_unique<ChannelSkew>(d);
  };
  return c;
}

}  // namespace flange::alt_reality
