// SPDX-License-Identifier: MIT
// The effect classes of the third reality, each defined by what it follows, its shape drawn per
// pair (README.md lists them). The class names are the other realities' (what a maintenance
// engineer acts on); none of the formulas is theirs.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "third_effect.h"
#include "third_random.h"

namespace flange::third_reality {

// What a draw may depend on: the pair's rate and the fitting session as an ideal sensor sees it.
struct DrawContext {
  double fs_hz = 6.0;
  double duration_s = 3600.0;  // the fitting session's
  double temp_lo_c = 20.0, temp_hi_c = 90.0;
  double clearance_lo_mm = 1.5, clearance_hi_mm = 10.0;
  double voltage_median_v = 5.0, voltage_high_v = 8.0;  // the 50th and 90th percentiles
  double age_lo_s = 0.0, age_hi_s = 86400.0;  // the fitting session's start, the held-out's end
};

struct ThirdClass {
  std::string name;
  std::vector<std::string> shapes;
  bool bias_type = true;    // a deterministic departure; false: noise-like (vibration, ADC)
  bool sets_noise = false;  // sized by setting the pair's noise (no amplitude to scale)
  std::function<EffectDraw(const std::string& shape, const DrawContext&, ThirdRandom&)> draw;
  std::function<std::unique_ptr<ThirdEffect>(const EffectDraw&, const SessionPlan&)> make;
};

ThirdClass temperature_offset_class();
ThirdClass temperature_gain_class();
ThirdClass sensor_thermal_lag_class();
ThirdClass temperature_reading_lag_class();
ThirdClass static_nonlinearity_class();
ThirdClass range_compression_class();
ThirdClass ageing_class();
ThirdClass channel_skew_class();
ThirdClass mains_pickup_class();
ThirdClass mount_vibration_class();
ThirdClass quantisation_class();
// Effects that belong to no class of the library: supply sags, backlash in the mount, a baseline
// that wanders differently in every session.
ThirdClass outside_class();

// The eleven classes in the order the chain applies them.
const std::vector<ThirdClass>& third_classes();
// A class by name (the eleven and "outside"); throws std::out_of_range for another name.
const ThirdClass& third_class(const std::string& name);

std::unique_ptr<ThirdEffect> make_third_effect(const EffectDraw& draw, const SessionPlan& plan);

}  // namespace flange::third_reality
