// SPDX-License-Identifier: MIT
// What flows through the sensor twin: the physical truth a scenario provides, the sample as each
// stage of the signal chain sees and changes it, and what the DAQ finally records.
#pragma once

#include "polynomial_sensor_model.h"

namespace flange::sim {

// The physical truth at one sampling instant, from a scenario.
struct TrueState {
  double t_s = 0.0;            // time since the start of the recording, increasing
  double clearance_mm = 0.0;   // sensor face to flange (bench: the micrometer reading)
  double temperature_c = 0.0;  // air and metal around the sensor (bench: the blower's heat)
};

// One sample inside the twin's chain (docs/sensor_twin.md, "Signal chain").
struct ChainSample {
  double t_s = 0.0;
  double clearance_mm = 0.0;    // gap the coil sees: the truth plus any mount motion
  double ambient_c = 0.0;       // true temperature around the sensor
  double coil_c = 0.0;          // temperature of the sensing coil (drives the sensor physics)
  double thermocouple_c = 0.0;  // what the temperature channel reports
  double voltage_v = 0.0;       // what the voltage channel carries
  RailClip clip = RailClip::kNone;
};

// One recorded sample: the two DAQ channels and whether the sensor output sat on a rail.
struct Reading {
  double t_s = 0.0;
  double temp_c = 0.0;
  double voltage_v = 0.0;
  RailClip clip = RailClip::kNone;
};

}  // namespace flange::sim
