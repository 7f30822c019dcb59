// SPDX-License-Identifier: MIT
#include "alt_classes.h"

#include <stdexcept>

namespace flange::alt_reality {

const std::vector<AltClass>& alt_classes() {
  static const std::vector<AltClass> classes = {mount_vibration_class(),
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

const AltClass& alt_class(const std::string& name) {
  static const AltClass outside = outside_class();
  if (name == outside.name) return outside;
  for (const AltClass& c : alt_classes()) {
    if (c.name == name) return c;
  }
  throw std::out_of_range("alt reality: no effect class " + name);
}

std::unique_ptr<AltEffect> make_alt_effect(const AltEffectDraw& draw, const SessionView& session) {
  return alt_class(draw.class_name).make(draw, session);
}

}  // namespace flange::alt_reality
