// SPDX-License-Identifier: MIT
// One bench session of the alternative reality as planned: its clock, its sensor's age, its
// protocols and its noise. The session clock starts at 0 in every session (a restarted DAQ);
// the sensor's age says when the session happened.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

#include "heating_protocols.h"
#include "micrometer_protocols.h"

namespace flange::alt_reality {

struct SessionPlan {
  double fs_hz = 6.0;
  double duration_s = 6000.0;
  double start_age_s = 0.0;  // the sensor's age (time since its calibration) at t = 0
  HeatingProtocol heating;
  MicrometerProtocol micrometer;
  double noise_v = 0.05;                    // white voltage noise, V
  double thermocouple_noise_c = 0.05;       // white noise on the temperature reading, degC
  double thermocouple_resolution_c = 0.01;  // the temperature module's display step, degC
  std::uint64_t noise_seed = 1;
};

nlohmann::json session_plan_json(const SessionPlan& plan);

}  // namespace flange::alt_reality
