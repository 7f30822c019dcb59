// SPDX-License-Identifier: MIT
#include "third_classes.h"

#include <stdexcept>

namespace flange::third_reality {

const std::vector<ThirdClass>& third_classes() {
  static const std::vector<ThirdClass> classes = {mount_vibration_class(),
                                                  sensor_thermal_lag_class(),
                                                  temperature_reading_lag_class(),
                                                  temperature_offset_class(),
                                                  temperature_gain_class(),
                                                  static_nonlinearity_class(),
                                                  range_compression_class(),
                                                  ageing_class(),
                                                  mains_pickup_class(),
                                                  channel_skew_class(),
                                                  quantisation_class()};
  return classes;
}

const ThirdClass& third_class(const std::string& name) {
  static const ThirdClass outside = outside_class();
  if (name == outside.name) return outside;
  for (const ThirdClass& c : third_classes()) {
    if (c.name == name) return c;
  }
  throw std::out_of_range("third reality: no effect class " + name);
}

std::unique_ptr<ThirdEffect> make_third_effect(const EffectDraw& draw, const SessionPlan& plan) {
  return third_class(draw.class_name).make(draw, plan);
}

}  // namespace flange::third_reality
