// SPDX-License-Identifier: MIT
// channel_skew: the voltage and temperature channels are not sampled at the same instant (a
// multiplexed DAQ, or a thermocouple module with its own latency). skew(t) > 0: the temperature
// reported with a sample was taken skew(t) earlier than the voltage; skew(t) < 0: the voltage is
// the older one. skew(t) = skew_s + drift_s_per_h h + drift_change_s_per_h2 h^2, h the session's
// clock in hours: a DAQ whose channel clocks drift apart (and settle) from the session's start.
// The delayed channel is interpolated linearly between past samples.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

#include "channel_skew_law.h"
#include "effects.h"

namespace flange::sim {
namespace {

// One channel's past samples, read back `delay_s` late. The instant read back, t - delay_s, never
// moves backwards while the delay changes by less than a second per second, so samples older than
// it are dropped.
class DelayLine {
 public:
  struct Point {
    double t_s;
    double value;
    RailClip clip;
  };

  // The channel's value (and rail flag) `delay_s` >= 0 before `now`, `now` stored first.
  Point delayed(const Point& now, double delay_s) {
    // The points still needed are history_[first_, end): what falls out of the window is
    // dropped from the front by moving first_, and the storage is compacted once the dropped
    // points are the larger part (a replay of a long session runs this on every sample).
    if (first_ > 64 && 2 * first_ > history_.size()) {
      history_.erase(history_.begin(), history_.begin() + static_cast<std::ptrdiff_t>(first_));
      first_ = 0;
    }
    history_.push_back(now);
    const double wanted_t_s = now.t_s - delay_s;
    while (history_.size() - first_ >= 2 && history_[first_ + 1].t_s <= wanted_t_s) ++first_;
    const Point& before = history_[first_];
    if (history_.size() - first_ == 1 || wanted_t_s <= before.t_s) return before;  // hold it
    const Point& after = history_[first_ + 1];
    const double weight = (wanted_t_s - before.t_s) / (after.t_s - before.t_s);
    // The rail flag travels with the value it describes.
    return {wanted_t_s, before.value + weight * (after.value - before.value),
            weight < 0.5 ? before.clip : after.clip};
  }

 private:
  std::vector<Point> history_;
  std::size_t first_ = 0;
};

class ChannelSkew final : public Effect {
 public:
  explicit ChannelSkew(const ChannelSkewLaw& law) : law_(law) {}

  void apply(ChainSample& sample) override {
    if (law_.zero()) return;
    const double skew_s = law_.at(sample.t_s);
    const DelayLine::Point voltage =
        voltage_.delayed({sample.t_s, sample.voltage_v, sample.clip}, std::max(0.0, -skew_s));
    const DelayLine::Point temperature = temperature_.delayed(
        {sample.t_s, sample.thermocouple_c, RailClip::kNone}, std::max(0.0, skew_s));
    sample.voltage_v = voltage.value;
    sample.clip = voltage.clip;
    sample.thermocouple_c = temperature.value;
  }

 private:
  ChannelSkewLaw law_;
  DelayLine voltage_, temperature_;
};

}  // namespace

EffectSpec channel_skew_effect() {
  EffectSpec spec;
  spec.name = "channel_skew";
  spec.summary = "time offset between the voltage and temperature channels";
  spec.stage = ChainStage::kAcquisition;
  spec.params = {
      {"skew_s", 0.25, -10.0, 10.0, "s",
       "at the session's start: > 0, the temperature is older than the voltage; < 0, the voltage "
       "is older"},
      {"drift_s_per_h", 0.0, -20.0, 20.0, "s/h",
       "how fast the skew changes on the session's clock (channel clocks that drift apart)"},
      {"drift_change_s_per_h2", 0.0, -20.0, 20.0, "s/h^2",
       "how fast that drift changes (a drift that settles)"},
  };
  spec.make = [](const ParamValues& p, const EffectContext&) {
    return std::make_unique<ChannelSkew>(
        ChannelSkewLaw{p.at("skew_s"), p.at("drift_s_per_h"), p.at("drift_change_s_per_h2")});
  };
  return spec;
}

}  // namespace flange::sim
