// SPDX-License-Identifier: MIT
// The effect classes of the alternative reality, each with at least two shapes written from
// their own formulas (README.md lists them). A class is what a maintenance engineer can act on;
// the shapes are deliberately not the sensor twin's formulas.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "alt_effect.h"
#include "alt_random.h"

namespace flange::alt_reality {

// What a draw may depend on: the pair's sampling rate and its fitting session.
struct DrawContext {
  double fs_hz = 6.0;
  double fit_start_age_s = 0.0;
  double fit_duration_s = 6000.0;
};

struct AltClass {
  std::string name;
  std::vector<std::string> shapes;
  bool bias_type = true;  // a deterministic departure; false: noise-like (vibration, ADC)
  std::function<AltEffectDraw(const std::string& shape, const DrawContext&, AltRandom&)> draw;
  std::function<std::unique_ptr<AltEffect>(const AltEffectDraw&, const SessionView&)> make;
};

AltClass temperature_offset_class();
AltClass temperature_gain_class();
AltClass sensor_thermal_lag_class();
AltClass temperature_reading_lag_class();
AltClass static_nonlinearity_class();
AltClass range_compression_class();
AltClass ageing_class();
AltClass channel_skew_class();
AltClass mains_pickup_class();
AltClass mount_vibration_class();
AltClass quantisation_class();
// Effects that belong to no class of the library: contact dropouts, a supply ripple, a
// magnetic hysteresis.
AltClass outside_class();

// Whether some mains standard (50 or 60 Hz) shows as a tone at `fs_hz` (mains_pickup.cpp).
bool mains_usable_at(double fs_hz);

// The eleven classes in the order the chain applies them.
const std::vector<AltClass>& alt_classes();
// A class by name (the eleven and "outside"); throws std::out_of_range for another name.
const AltClass& alt_class(const std::string& name);

// An instance of `draw` for one pass over `session`.
std::unique_ptr<AltEffect> make_alt_effect(const AltEffectDraw& draw, const SessionView& session);

}  // namespace flange::alt_reality
