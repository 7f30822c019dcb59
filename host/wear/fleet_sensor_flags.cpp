// SPDX-License-Identifier: MIT
#include "fleet_sensor_flags.h"

namespace flange::host {

void latch_sensor_flags(FleetWear& fleet, const std::vector<WheelHistory>& histories,
                        const SensorFlags& previous) {
  std::map<SensorFlagKey, const std::vector<MaintenanceMark>*> maintenance;
  for (const WheelHistory& history : histories) {
    maintenance[{history.wheel.locomotive, history.wheel.axle, history.wheel.side}] =
        &history.maintenance;
  }
  static const std::vector<MaintenanceMark> none;
  for (WheelWear& wheel : fleet.wheels) {
    const SensorFlagKey key{wheel.wheel.locomotive, wheel.wheel.axle, wheel.wheel.side};
    std::optional<SensorFlag> kept;
    if (const auto found = previous.find(key); found != previous.end()) kept = found->second;
    if (wheel.runs.empty()) {
      wheel.sensor_flag = kept;
      continue;
    }
    const auto events = maintenance.find(key);
    wheel.sensor_flag = next_sensor_flag(kept, wheel.sensor_fault.has_value(), wheel.runs.back().at,
                                         events == maintenance.end() ? none : *events->second);
    if (wheel.sensor_flag && wheel.sensor_flag->latched() && wheel.status != "too few runs") {
      wheel.status = "sensor fault";
    }
  }
}

}  // namespace flange::host
