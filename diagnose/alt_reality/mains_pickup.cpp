// SPDX-License-Identifier: MIT
// Mains pickup on the voltage cable, evaluated at the sampling instants (so it aliases) on the
// sensor's age, the absolute clock: a session's phase is wherever the mains happens to be when
// it starts. Shapes:
//   odd_harmonics: the nominal 50 or 60 Hz with its 3rd and 5th harmonics, each its own phase
//   drifting:      the grid's frequency off nominal by offset_hz and wandering by wander_hz
//                  over wander_period_s, with a 2nd harmonic
// The standard is one whose fundamental does not alias to within 0.3 Hz of DC or Nyquist at the
// pair's rate (there a tone is an offset or has no stable phase).
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

double alias_hz(double f_hz, double fs_hz) {
  const double folded = std::fmod(f_hz, fs_hz);
  return std::min(folded, fs_hz - folded);
}

class MainsPickup final : public AltEffect {
 public:
  explicit MainsPickup(const AltEffectDraw& d) : drifting_(d.shape == "drifting"), p_(d.params) {}

  void cable(AltSample& s) override {
    const double t = s.age_s;
    const double nominal = p_.at("mains_hz");
    double cycles = nominal * t;  // the fundamental's phase in cycles
    if (drifting_) {
      const double period = p_.at("wander_period_s");
      cycles += p_.at("offset_hz") * t - p_.at("wander_hz") * period / (2.0 * std::numbers::pi) *
                                             std::cos(2.0 * std::numbers::pi * t / period);
    }
    const double a = p_.at("amplitude_v");
    const double phase = 2.0 * std::numbers::pi * std::fmod(cycles, 1.0);
    s.voltage_v += a * std::sin(phase + p_.at("phase_1_rad"));
    if (drifting_) {
      s.voltage_v += a * p_.at("ratio_2") * std::sin(2.0 * phase + p_.at("phase_2_rad"));
    } else {
      s.voltage_v += a * p_.at("ratio_3") * std::sin(3.0 * phase + p_.at("phase_3_rad"));
      s.voltage_v += a * p_.at("ratio_5") * std::sin(5.0 * phase + p_.at("phase_5_rad"));
    }
  }

 private:
  bool drifting_;
  AltParams p_;
};

double draw_standard(double fs_hz, AltRandom& random) {
  std::vector<double> usable;
  for (const double f : {50.0, 60.0}) {
    const double a = alias_hz(f, fs_hz);
    if (a > 0.3 && a < 0.5 * fs_hz - 0.3) usable.push_back(f);
  }
  if (usable.empty()) throw std::invalid_argument("mains_pickup: no usable standard at this rate");
  return usable[static_cast<std::size_t>(random.index(static_cast<int>(usable.size())))];
}

}  // namespace

AltClass mains_pickup_class() {
  AltClass c;
  c.name = "mains_pickup";
  c.shapes = {"odd_harmonics", "drifting"};
  c.draw = [](const std::string& shape, const DrawContext& context, AltRandom& random) {
    AltEffectDraw d{"mains_pickup", shape, {}, "amplitude_v"};
    d.params["amplitude_v"] = 1.0;
    d.params["mains_hz"] = draw_standard(context.fs_hz, random);
    for (const char* key : {"phase_1_rad", "phase_2_rad", "phase_3_rad", "phase_5_rad"}) {
      d.params[key] = random.uniform(-std::numbers::pi, std::numbers::pi);
    }
    if (shape == "odd_harmonics") {
      d.params.erase("phase_2_rad");
      d.params["ratio_3"] = random.uniform(0.2, 0.6);
      d.params["ratio_5"] = random.uniform(0.0, 0.3);
    } else if (shape == "drifting") {
      d.params.erase("phase_3_rad");
      d.params.erase("phase_5_rad");
      d.params["ratio_2"] = random.uniform(0.1, 0.5);
      d.params["offset_hz"] = random.sign() * random.uniform(0.002, 0.02);
      d.params["wander_hz"] = random.uniform(0.0, 0.01);
      d.params["wander_period_s"] = random.uniform(600.0, 3600.0);
    } else {
      throw std::invalid_argument("mains_pickup: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView&) {
    return std::make_unique<MainsPickup>(d);
  };
  return c;
}

bool mains_usable_at(double fs_hz) {
  for (const double f : {50.0, 60.0}) {
    const double a = alias_hz(f, fs_hz);
    if (a > 0.3 && a < 0.5 * fs_hz - 0.3) return true;
  }
  return false;
}

}  // namespace flange::alt_reality
