// SPDX-License-Identifier: MIT
// mains_pickup: 50 Hz (or 60 Hz) and its harmonics coupled into the voltage cable, from the
// lab's mains or the locomotive's 25 kV 50 Hz traction supply. The tones are evaluated at the
// sample instants (the DAQ samples, it does not average), so a tone at k f lands where
// aliasing puts it: alias_frequency_hz(k f, fs), e.g. 50 Hz at 6 Hz shows at 2 Hz.
#include <cmath>
#include <numbers>
#include <vector>

#include "effects.h"

namespace flange::sim {
namespace {

class MainsPickup final : public Effect {
 public:
  explicit MainsPickup(const ParamValues& p) {
    const int harmonics = static_cast<int>(p.at("harmonics"));
    double amplitude_v = p.at("amplitude_v");
    const double phase_rad = p.at("phase_deg") * std::numbers::pi / 180.0;
    for (int k = 1; k <= harmonics; ++k) {
      tones_.push_back({amplitude_v, 2.0 * std::numbers::pi * k * p.at("mains_hz"), k * phase_rad});
      amplitude_v *= p.at("harmonic_ratio");
    }
  }

  void apply(ChainSample& sample) override {
    for (std::size_t k = 0; k < tones_.size(); ++k) sample.voltage_v += tone_at(tones_[k], sample.t_s);
  }

  int time_terms() const override { return static_cast<int>(tones_.size()); }
  double time_term(int term, double t_s) const override {
    return tone_at(tones_[static_cast<std::size_t>(term)], t_s);
  }

 private:
  struct Tone {
    double amplitude_v;
    double angular_hz;
    double phase_rad;
  };
  static double tone_at(const Tone& tone, double t_s) {
    return tone.amplitude_v * std::sin(tone.angular_hz * t_s + tone.phase_rad);
  }

  std::vector<Tone> tones_;
};

}  // namespace

EffectSpec mains_pickup_effect() {
  EffectSpec spec;
  spec.name = "mains_pickup";
  spec.summary = "mains frequency and harmonics on the voltage cable, aliased by the sampling";
  spec.stage = ChainStage::kWiring;
  spec.params = {
      {"amplitude_v", 0.02, 0.0, 1.0, "V", "amplitude of the fundamental"},
      {"mains_hz", 50.0, 40.0, 70.0, "Hz", "mains frequency (Ethiopia and Djibouti: 50 Hz)"},
      {"harmonics", 3.0, 1.0, 20.0, "", "number of tones: the fundamental and its multiples", true},
      {"harmonic_ratio", 0.3, 0.0, 1.0, "", "amplitude ratio of each harmonic to the one below"},
      {"phase_deg", 30.0, -360.0, 360.0, "deg", "phase of the fundamental at t = 0 (k-th: k x)"},
  };
  spec.make = [](const ParamValues& p, const EffectContext&) {
    return std::make_unique<MainsPickup>(p);
  };
  return spec;
}

}  // namespace flange::sim
