// SPDX-License-Identifier: MIT
// One session of the third bench as planned: its rate, length and sensor age (the clock starts at
// 0 in every session; the age says when it happened), its heating and micrometer, its logger and
// its noise.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>

#include "heating_plan.h"
#include "logger_timeline.h"
#include "micrometer_plan.h"

namespace flange::third_reality {

struct SessionPlan {
  double fs_hz = 6.0;  // 6-100 Hz
  double duration_s = 3600.0;
  double start_age_s = 0.0;  // the sensor's age (time since its calibration) at t = 0
  HeatingPlan heating;
  MicrometerPlan micrometer;
  LoggerPlan logger;
  double noise_v = 0.03;               // white voltage noise, V
  double thermocouple_noise_c = 0.05;  // white noise of the temperature reading, degC
  double thermocouple_step_c = 0.1;    // the temperature module's display step, degC
  std::uint64_t noise_seed = 1;
};

nlohmann::json session_plan_json(const SessionPlan& plan);

}  // namespace flange::third_reality
