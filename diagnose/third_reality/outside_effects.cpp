// SPDX-License-Identifier: MIT
// Effects that no class of the library describes: the supply sagging in episodes (the output
// scaled down by a depth while a heavy load runs, at other times in every session), backlash in
// the mount (the disk lags the micrometer by a play when it turns back), and a baseline that
// wanders along a random smooth function of the clock drawn afresh for every session.
#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

#include "third_classes.h"

namespace flange::third_reality {
namespace {

// Each session draws its own events from the effect's seed and the session's noise seed.
std::uint64_t session_stream(const EffectDraw& d, const SessionPlan& plan) {
  return static_cast<std::uint64_t>(d.params.at("event_seed")) * 0x9E3779B1ULL ^ plan.noise_seed;
}

class SupplySags : public ThirdEffect {
 public:
  SupplySags(const EffectDraw& d, const SessionPlan& plan) : depth_(d.params.at("depth")) {
    ThirdRandom random(session_stream(d, plan));
    const int count = 2 + random.below(7);
    for (int i = 0; i < count; ++i) {
      const double start = random.uniform(0.0, plan.duration_s);
      starts_.push_back(start);
      ends_.push_back(start + random.uniform(30.0, 300.0));
    }
  }
  void sense(const ChannelPass& pass, std::vector<double>& v) const override {
    constexpr double kEdgeS = 10.0;
    for (std::size_t k = 0; k < v.size(); ++k) {
      double sag = 0.0;
      for (std::size_t i = 0; i < starts_.size(); ++i) {
        const double into = std::min(pass.instant_s[k] - starts_[i], ends_[i] - pass.instant_s[k]);
        if (into > 0.0)
          sag = std::max(
              sag, into >= kEdgeS ? 1.0 : 0.5 - 0.5 * std::cos(std::numbers::pi * into / kEdgeS));
      }
      v[k] *= 1.0 - depth_ * sag;
    }
  }

 private:
  double depth_;
  std::vector<double> starts_, ends_;
};

class Backlash : public ThirdEffect {
 public:
  explicit Backlash(const EffectDraw& d) : play_mm_(d.params.at("play_mm")) {}
  void move(const ChannelPass&, std::vector<double>& clearance_mm) const override {
    if (clearance_mm.empty()) return;
    double disk = clearance_mm[0];
    for (double& d : clearance_mm) {
      disk = std::clamp(disk, d - play_mm_, d + play_mm_);
      d = disk;
    }
  }

 private:
  double play_mm_;
};

class WanderingBaseline : public ThirdEffect {
 public:
  WanderingBaseline(const EffectDraw& d, const SessionPlan& plan)
      : amplitude_v_(d.params.at("amplitude_v")), duration_s_(plan.duration_s) {
    ThirdRandom random(session_stream(d, plan));
    f_ = draw_smooth_function(false, random);
  }
  void sense(const ChannelPass& pass, std::vector<double>& v) const override {
    for (std::size_t k = 0; k < v.size(); ++k) {
      v[k] += amplitude_v_ * f_(pass.instant_s[k] / duration_s_);
    }
  }

 private:
  double amplitude_v_, duration_s_;
  SmoothFunction f_;
};

}  // namespace

ThirdClass outside_class() {
  ThirdClass c;
  c.name = "outside";
  c.shapes = {"supply_sags", "mount_backlash", "wandering_baseline"};
  c.draw = [](const std::string& shape, const DrawContext&, ThirdRandom& random) {
    EffectDraw d{"outside", shape, {}, ""};
    d.params["event_seed"] = random.child_seed();
    if (shape == "supply_sags") d.amplitude_key = "depth";
    if (shape == "mount_backlash") d.amplitude_key = "play_mm";
    if (shape == "wandering_baseline") d.amplitude_key = "amplitude_v";
    d.params[d.amplitude_key] = shape == "supply_sags" ? 0.01 : 0.05;
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan& plan) -> std::unique_ptr<ThirdEffect> {
    if (d.shape == "supply_sags") return std::make_unique<SupplySags>(d, plan);
    if (d.shape == "mount_backlash") return std::make_unique<Backlash>(d);
    return std::make_unique<WanderingBaseline>(d, plan);
  };
  return c;
}

}  // namespace flange::third_reality
