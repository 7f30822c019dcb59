// SPDX-License-Identifier: MIT
// channel_skew: the voltage and temperature channels are not sampled at the same instant (a
// multiplexed DAQ, or a thermocouple module with its own latency). skew_s > 0: the temperature
// reported with a sample was taken skew_s earlier than the voltage; skew_s < 0: the voltage is
// the older one. The delayed channel is interpolated linearly between past samples.
#include <cmath>
#include <deque>

#include "effects.h"

namespace flange::sim {
namespace {

class ChannelSkew final : public Effect {
 public:
  explicit ChannelSkew(double skew_s) : skew_s_(skew_s) {}

  void apply(ChainSample& sample) override {
    if (skew_s_ == 0.0) return;
    const bool delay_voltage = skew_s_ < 0.0;
    double& channel = delay_voltage ? sample.voltage_v : sample.thermocouple_c;
    history_.push_back({sample.t_s, channel, sample.clip});
    const double wanted_t_s = sample.t_s - std::abs(skew_s_);
    // Keep one sample at or before the wanted instant; older ones are never needed again.
    while (history_.size() >= 2 && history_[1].t_s <= wanted_t_s) history_.pop_front();
    const Point& before = history_.front();
    if (history_.size() == 1 || wanted_t_s <= before.t_s) {
      channel = before.value;  // before the record began: hold the first value
      if (delay_voltage) sample.clip = before.clip;
      return;
    }
    const Point& after = history_[1];
    const double weight = (wanted_t_s - before.t_s) / (after.t_s - before.t_s);
    channel = before.value + weight * (after.value - before.value);
    // The rail flag travels with the voltage it describes.
    if (delay_voltage) sample.clip = weight < 0.5 ? before.clip : after.clip;
  }

 private:
  struct Point {
    double t_s;
    double value;
    RailClip clip;
  };
  double skew_s_;
  std::deque<Point> history_;
};

}  // namespace

EffectSpec channel_skew_effect() {
  EffectSpec spec;
  spec.name = "channel_skew";
  spec.summary = "time offset between the voltage and temperature channels";
  spec.stage = ChainStage::kAcquisition;
  spec.params = {
      {"skew_s", 0.25, -10.0, 10.0, "s",
       "> 0: the temperature is older than the voltage; < 0: the voltage is older"},
  };
  spec.make = [](const ParamValues& p, const EffectContext&) {
    return std::make_unique<ChannelSkew>(p.at("skew_s"));
  };
  return spec;
}

}  // namespace flange::sim
