// SPDX-License-Identifier: MIT
// Mount vibration: the sensor bracket moves relative to the disk; the motion adds to the
// clearance the coil sees and is evaluated at the sampling instants (so it aliases). Shapes:
//   narrow_resonance: a bracket resonance at resonance_hz, bandwidth_hz wide: eight tones with
//                     a Gaussian spread of amplitudes about the resonance, random phases
//   impacts:          Poisson knocks at rate_per_s, each a ring at ring_hz decaying with
//                     decay_s and a Rayleigh-distributed size (heavy-tailed, not Gaussian)
// amplitude_mm scales the motion (its RMS is set by the pair's drawn size).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

constexpr int kResonanceTones = 8;

class NarrowResonance final : public AltEffect {
 public:
  NarrowResonance(const AltEffectDraw& d, const SessionView& session) {
    AltRandom random(static_cast<std::uint64_t>(d.params.at("seed")) ^
                     static_cast<std::uint64_t>(session.plan->start_age_s * 1000.0));
    const double f0 = d.params.at("resonance_hz"), bw = d.params.at("bandwidth_hz");
    for (int k = 0; k < kResonanceTones; ++k) {
      const double offset = bw * (random.unit() - 0.5) * 2.0;
      tones_.push_back({2.0 * std::numbers::pi * (f0 + offset),
                        d.params.at("amplitude_mm") * std::exp(-2.0 * offset * offset / (bw * bw)),
                        random.uniform(0.0, 2.0 * std::numbers::pi)});
    }
  }

  void mount(AltSample& s) override {
    for (const Tone& tone : tones_) {
      s.clearance_mm += tone.amplitude_mm * std::sin(tone.angular_hz * s.t_s + tone.phase);
    }
  }

 private:
  struct Tone {
    double angular_hz, amplitude_mm, phase;
  };
  std::vector<Tone> tones_;
};

class Impacts final : public AltEffect {
 public:
  Impacts(const AltEffectDraw& d, const SessionView& session)
      : angular_hz_(2.0 * std::numbers::pi * d.params.at("ring_hz")),
        decay_s_(d.params.at("decay_s")) {
    AltRandom random(static_cast<std::uint64_t>(d.params.at("seed")) ^
                     static_cast<std::uint64_t>(session.plan->start_age_s * 1000.0));
    const double rate = d.params.at("rate_per_s");
    const double scale = d.params.at("amplitude_mm");
    // Knocks from a little before the session (a skewed channel looks back) to its end.
    for (double t = -20.0; t < session.plan->duration_s + 1.0;
         t += -std::log(random.unit()) / rate) {
      knocks_.push_back({t, scale * std::sqrt(-2.0 * std::log(random.unit()))});
    }
  }

  void mount(AltSample& s) override {
    // Knocks older than 12 decay times have rung out (e^-12).
    const auto first = std::lower_bound(knocks_.begin(), knocks_.end(), s.t_s - 12.0 * decay_s_,
                                        [](const Knock& k, double t) { return k.t_s < t; });
    for (auto k = first; k != knocks_.end() && k->t_s <= s.t_s; ++k) {
      const double age = s.t_s - k->t_s;
      s.clearance_mm += k->size_mm * std::exp(-age / decay_s_) * std::sin(angular_hz_ * age);
    }
  }

 private:
  struct Knock {
    double t_s, size_mm;
  };
  double angular_hz_, decay_s_;
  std::vector<Knock> knocks_;
};

}  // namespace

AltClass mount_vibration_class() {
  AltClass c;
  c.name = "mount_vibration";
  c.shapes = {"narrow_resonance", "impacts"};
  c.bias_type = false;
  c.draw = [](const std::string& shape, const DrawContext&, AltRandom& random) {
    AltEffectDraw d{"mount_vibration", shape, {}, "amplitude_mm"};
    d.params["amplitude_mm"] = 1.0;
    d.params["seed"] = random.sub_seed();
    if (shape == "narrow_resonance") {
      d.params["resonance_hz"] = random.uniform(12.0, 45.0);
      d.params["bandwidth_hz"] = random.uniform(0.2, 2.0);
    } else if (shape == "impacts") {
      d.params["rate_per_s"] = random.uniform(0.5, 3.0);
      d.params["ring_hz"] = random.uniform(15.0, 35.0);
      d.params["decay_s"] = random.uniform(0.05, 0.3);
    } else {
      throw std::invalid_argument("mount_vibration: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView& session) -> std::unique_ptr<AltEffect> {
    if (d.shape == "impacts") return std::make_unique<Impacts>(d, session);
    return std::make_unique<NarrowResonance>(d, session);
  };
  return c;
}

}  // namespace flange::alt_reality
