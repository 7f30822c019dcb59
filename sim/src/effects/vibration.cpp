// SPDX-License-Identifier: MIT
// vibration: the sensor bracket moves relative to the bogie (and so to the flange) with
// band-limited random motion. It is a sum of random-phase tones spread over the band and
// evaluated at each sample time, so sampling below twice the band's top frequency aliases it
// exactly as a real DAQ would.
#include <cmath>
#include <numbers>
#include <vector>

#include "effects.h"
#include "gaussian_source.h"

namespace flange::sim {
namespace {

// Enough tones that the band looks continuous in a few-minute record, few enough to be cheap.
constexpr int kTones = 32;

class Vibration final : public Effect {
 public:
  Vibration(const ParamValues& p, const EffectContext& context) {
    GaussianSource random(context.seed);
    const double low = p.at("f_low_hz");
    const double width = p.at("f_high_hz") - low;
    amplitude_mm_ = p.at("rms_mm") * std::sqrt(2.0 / kTones);
    for (int k = 0; k < kTones; ++k) {
      // One tone at a random place in each of kTones equal slices of the band.
      const double frequency_hz = low + width * (k + random.uniform()) / kTones;
      angular_hz_.push_back(2.0 * std::numbers::pi * frequency_hz);
      phase_rad_.push_back(2.0 * std::numbers::pi * random.uniform());
    }
  }

  void apply(ChainSample& sample) override {
    double motion_mm = 0.0;
    for (std::size_t k = 0; k < angular_hz_.size(); ++k) {
      motion_mm += std::sin(angular_hz_[k] * sample.t_s + phase_rad_[k]);
    }
    sample.clearance_mm += amplitude_mm_ * motion_mm;
  }

 private:
  double amplitude_mm_ = 0.0;
  std::vector<double> angular_hz_;
  std::vector<double> phase_rad_;
};

}  // namespace

EffectSpec vibration_effect() {
  EffectSpec spec;
  spec.name = "vibration";
  spec.summary = "band-limited random motion of the sensor mount, added to the clearance";
  spec.stage = ChainStage::kMount;
  spec.params = {
      {"rms_mm", 0.05, 0.0, 5.0, "mm", "RMS of the mount motion"},
      {"f_low_hz", 10.0, 0.01, 1000.0, "Hz", "lower edge of the band"},
      {"f_high_hz", 40.0, 0.01, 1000.0, "Hz", "upper edge of the band"},
  };
  spec.check_together = [](const ParamValues& p) -> std::string {
    return p.at("f_low_hz") < p.at("f_high_hz") ? "" : "f_low_hz must be below f_high_hz";
  };
  spec.make = [](const ParamValues& p, const EffectContext& context) {
    return std::make_unique<Vibration>(p, context);
  };
  return spec;
}

}  // namespace flange::sim
