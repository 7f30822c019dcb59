// SPDX-License-Identifier: MIT
// The second fleet reality's sensor: an eddy-current law of its own, not a polynomial. The
// output saturates exponentially with the clearance and both its scale and its length shrink
// and stretch with the coil's temperature:
//   V = g Vsat (1 - k_s (T - 20)) (1 - exp(-(d + d0) / (lambda (1 + k_l (T - 20))))) + o + drift
// with Vsat = 13 V and lambda = 9 mm (2.6 V over a new flange's 2 mm, 8.7 V at 10 mm), k_s =
// 0.0016 /degC and k_l = 0.0009 /degC (the output drops as the coil warms), and each unit's own
// gain g, zero offset d0 and voltage offset o. The coil's temperature follows a law of its own
// (coil_temperature_c); the thermocouple reads it with its own noise and resolution.
#pragma once

namespace flange::fleet_alt {

// One sensor unit: what sets it apart from the type's nominal law.
struct SensorUnit {
  double gain = 1.0;             // g: about 1 +- 0.8 %
  double zero_mm = 0.0;          // d0: about +- 0.05 mm
  double offset_v = 0.0;         // o: about +- 0.03 V
  double drift_v_per_day = 0.0;  // a drifting unit's offset creep (0 for a healthy one)
  int drift_start_day = 0;       // the day (from the fleet's first) the creep starts
};

inline constexpr double kOutputLowV = 0.0, kOutputHighV = 10.0;  // the supply's rails
inline constexpr double kNoiseV = 0.012;                         // white noise at the output
inline constexpr double kConverterStepV = 10.0 / 4096.0;         // a 12-bit converter over 10 V

// The unit's noiseless output (V, not clipped) at clearance `clearance_mm` and coil
// temperature `coil_c` on fleet day `day` (the drift's age).
double sensor_voltage(const SensorUnit& unit, double clearance_mm, double coil_c, double day);

// What the converter records: clipped to the rails, rounded to its step.
double recorded_voltage(double volts);

// The coil's temperature `t_s` seconds into the morning's service: the parked coil starts
// `parked_rise_c` above the ambient and warms towards ambient + 15 degC with a 520 s time
// constant (eddy-current and bearing heat), plus this wheel's own offset.
double coil_temperature_c(double ambient_c, double t_s, double parked_rise_c,
                          double wheel_offset_c);

// The thermocouple's reading of `coil_c`: 0.1 degC resolution (the noise is the caller's).
double thermocouple_reading_c(double coil_c);

}  // namespace flange::fleet_alt
