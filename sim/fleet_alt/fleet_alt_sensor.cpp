// SPDX-License-Identifier: MIT
#include "fleet_alt_sensor.h"

#include <algorithm>
#include <cmath>

namespace flange::fleet_alt {
namespace {

constexpr double kSaturationV = 13.0;
constexpr double kLengthMm = 9.0;
constexpr double kScalePerC = 0.0016;
constexpr double kLengthPerC = 0.0009;
constexpr double kReferenceC = 20.0;

constexpr double kWarmRiseC = 15.0;   // the coil's rise over the ambient once warm
constexpr double kWarmTimeS = 520.0;  // its time constant
constexpr double kThermocoupleStepC = 0.1;

}  // namespace

double sensor_voltage(const SensorUnit& unit, double clearance_mm, double coil_c, double day) {
  const double dt = coil_c - kReferenceC;
  const double length = kLengthMm * (1.0 + kLengthPerC * dt);
  const double shape = 1.0 - std::exp(-(clearance_mm + unit.zero_mm) / length);
  const double drift =
      day > unit.drift_start_day ? unit.drift_v_per_day * (day - unit.drift_start_day) : 0.0;
  return unit.gain * kSaturationV * (1.0 - kScalePerC * dt) * shape + unit.offset_v + drift;
}

double recorded_voltage(double volts) {
  const double clipped = std::clamp(volts, kOutputLowV, kOutputHighV);
  return std::round(clipped / kConverterStepV) * kConverterStepV;
}

double coil_temperature_c(double ambient_c, double t_s, double parked_rise_c,
                          double wheel_offset_c) {
  const double start = ambient_c + parked_rise_c;
  const double warm = ambient_c + kWarmRiseC;
  return warm + (start - warm) * std::exp(-t_s / kWarmTimeS) + wheel_offset_c;
}

double thermocouple_reading_c(double coil_c) {
  return std::round(coil_c / kThermocoupleStepC) * kThermocoupleStepC;
}

}  // namespace flange::fleet_alt
