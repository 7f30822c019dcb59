// SPDX-License-Identifier: MIT
// Every wheel's sensor flag carried from the last estimate to this one (sensor_flag_latch.h):
// the flags the store kept in, each wheel's flag after this estimate out, and a latched flag
// makes its wheel a sensor fault whatever this estimate's drift search says.
#pragma once

#include <map>
#include <string>
#include <tuple>
#include <vector>

#include "fleet_wear.h"
#include "sensor_flag_latch.h"
#include "wheel_history.h"

namespace flange::host {

// By locomotive, axle, side.
using SensorFlagKey = std::tuple<std::string, int, std::string>;
using SensorFlags = std::map<SensorFlagKey, SensorFlag>;

// Sets each wheel's sensor_flag from `previous` (the flags kept by the last estimate), this
// estimate's sensor_fault and the wheel's maintenance in `histories`; a latched flag's wheel
// gets the status "sensor fault" (unless it has too few runs for any status).
void latch_sensor_flags(FleetWear& fleet, const std::vector<WheelHistory>& histories,
                        const SensorFlags& previous);

}  // namespace flange::host
