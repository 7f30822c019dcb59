// SPDX-License-Identifier: MIT
// Classes that follow a frequency band: the mount's vibration moves the clearance by A m(t)
// (band_motion.h: narrow-band random motion or tones, aliased at 6-12.5 Hz sampling), and the
// mains adds A w(t) on the cable (mains_wave.h: 50 or 60 Hz wandering, with harmonics).
#include <memory>

#include "band_motion.h"
#include "mains_wave.h"
#include "third_classes.h"

namespace flange::third_reality {
namespace {

class Vibration : public ThirdEffect {
 public:
  explicit Vibration(const EffectDraw& d)
      : motion_(get_band_motion(d.params)), amplitude_mm_(d.params.at("amplitude_mm")) {}
  void move(const ChannelPass& pass, std::vector<double>& clearance_mm) const override {
    for (std::size_t k = 0; k < clearance_mm.size(); ++k) {
      clearance_mm[k] += amplitude_mm_ * motion_(pass.instant_s[k]);
    }
  }

 private:
  BandMotion motion_;
  double amplitude_mm_;
};

class Mains : public ThirdEffect {
 public:
  explicit Mains(const EffectDraw& d)
      : wave_(get_mains_wave(d.params)), amplitude_v_(d.params.at("amplitude_v")) {}
  void pick_up(const ChannelPass& pass, std::vector<double>& v) const override {
    for (std::size_t k = 0; k < v.size(); ++k) v[k] += amplitude_v_ * wave_(pass.age_s(k));
  }

 private:
  MainsWave wave_;
  double amplitude_v_;
};

}  // namespace

ThirdClass mount_vibration_class() {
  ThirdClass c;
  c.name = "mount_vibration";
  c.shapes = {"narrow_band", "tones"};
  c.bias_type = false;
  c.draw = [](const std::string& shape, const DrawContext& context, ThirdRandom& random) {
    EffectDraw d{"mount_vibration", shape, {}, "amplitude_mm"};
    BandMotion motion = draw_band_motion(context.fs_hz, random);
    motion.narrow_band = shape == "narrow_band";
    put_band_motion(motion, d.params);
    d.params["amplitude_mm"] = 0.02;
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<Vibration>(d);
  };
  return c;
}

ThirdClass mains_pickup_class() {
  ThirdClass c;
  c.name = "mains_pickup";
  c.shapes = {"wandering", "wandering_with_harmonics"};
  c.draw = [](const std::string& shape, const DrawContext& context, ThirdRandom& random) {
    EffectDraw d{"mains_pickup", shape, {}, "amplitude_v"};
    double nominal = usable_mains_hz(context.fs_hz, random);
    if (nominal == 0.0) nominal = 50.0;  // the pair's rate is drawn so that this does not happen
    MainsWave wave = draw_mains_wave(nominal, random);
    if (shape == "wandering") wave.harmonic = {};
    put_mains_wave(wave, d.params);
    d.params["amplitude_v"] = 0.05;
    return d;
  };
  c.make = [](const EffectDraw& d, const SessionPlan&) -> std::unique_ptr<ThirdEffect> {
    return std::make_unique<Mains>(d);
  };
  return c;
}

}  // namespace flange::third_reality
