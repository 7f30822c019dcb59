// SPDX-License-Identifier: MIT
// Effects that belong to no class of the library (a diagnosis should not name one). Shapes:
//   contact_dropouts:    an intermittent connector: at rate_per_s the voltage falls to
//                        level_v for 0.2-0.6 s
//   supply_ripple:       the sensor's supply sags and recovers with period_s, scaling the
//                        output: V' = V (1 + A sin(2 pi age / period_s + phase))
//   magnetic_hysteresis: the output depends on the direction of the last clearance move:
//                        V' = V + A (+1 after an opening move, -1 after a closing one)
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "alt_classes.h"

namespace flange::alt_reality {
namespace {

class ContactDropouts final : public AltEffect {
 public:
  ContactDropouts(const AltEffectDraw& d, const SessionView& session)
      : level_v_(d.params.at("level_v")) {
    AltRandom random(static_cast<std::uint64_t>(d.params.at("seed")) ^
                     static_cast<std::uint64_t>(session.plan->start_age_s * 1000.0));
    const double rate = d.params.at("rate_per_s");
    for (double t = -random.uniform(0.0, 1.0 / rate); t < session.plan->duration_s;) {
      t += -std::log(random.unit()) / rate;
      const double length = random.uniform(0.2, 0.6);
      gaps_.push_back({t, t + length});
      t += length;
    }
  }

  void cable(AltSample& s) override {
    while (next_ < gaps_.size() && gaps_[next_].second < s.t_s) ++next_;
    if (next_ < gaps_.size() && gaps_[next_].first <= s.t_s) s.voltage_v = level_v_;
  }

 private:
  double level_v_;
  std::vector<std::pair<double, double>> gaps_;
  std::size_t next_ = 0;
};

class SupplyRipple final : public AltEffect {
 public:
  explicit SupplyRipple(const AltEffectDraw& d)
      : amplitude_(d.params.at("amplitude")),
        period_s_(d.params.at("period_s")),
        phase_(d.params.at("phase_rad")) {}

  void characteristic(AltSample& s) override {
    const double cycles = std::fmod(s.age_s / period_s_, 1.0);
    s.voltage_v *= 1.0 + amplitude_ * std::sin(2.0 * std::numbers::pi * cycles + phase_);
  }

 private:
  double amplitude_, period_s_, phase_;
};

class MagneticHysteresis final : public AltEffect {
 public:
  explicit MagneticHysteresis(const AltEffectDraw& d) : amplitude_v_(d.params.at("amplitude_v")) {}

  void characteristic(AltSample& s) override {
    if (started_ && std::abs(s.clearance_mm - last_mm_) > 1e-6) {
      direction_ = s.clearance_mm > last_mm_ ? 1.0 : -1.0;
    }
    started_ = true;
    last_mm_ = s.clearance_mm;
    s.voltage_v += amplitude_v_ * direction_;
  }

 private:
  double amplitude_v_;
  bool started_ = false;
  double last_mm_ = 0.0, direction_ = 1.0;
};

}  // namespace

AltClass outside_class() {
  AltClass c;
  c.name = "outside";
  c.shapes = {"contact_dropouts", "supply_ripple", "magnetic_hysteresis"};
  c.draw = [](const std::string& shape, const DrawContext&, AltRandom& random) {
    AltEffectDraw d{"outside", shape, {}, ""};
    if (shape == "contact_dropouts") {
      d.params["rate_per_s"] = random.uniform(0.002, 0.01);
      d.params["level_v"] = random.uniform(0.0, 0.3);
      d.params["seed"] = random.sub_seed();
    } else if (shape == "supply_ripple") {
      d.amplitude_key = "amplitude";
      d.params["amplitude"] = 1.0;
      d.params["period_s"] = random.uniform(600.0, 1800.0);
      d.params["phase_rad"] = random.uniform(-std::numbers::pi, std::numbers::pi);
    } else if (shape == "magnetic_hysteresis") {
      d.amplitude_key = "amplitude_v";
      d.params["amplitude_v"] = random.sign();
    } else {
      throw std::invalid_argument("outside: no shape " + shape);
    }
    return d;
  };
  c.make = [](const AltEffectDraw& d, const SessionView& session) -> std::unique_ptr<AltEffect> {
    if (d.shape == "contact_dropouts") return std::make_unique<ContactDropouts>(d, session);
    if (d.shape == "supply_ripple") return std::make_unique<SupplyRipple>(d);
    return std::make_unique<MagneticHysteresis>(d);
  };
  return c;
}

}  // namespace flange::alt_reality
