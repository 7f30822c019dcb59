// SPDX-License-Identifier: MIT
#include "sensor_flag_latch.h"

#include <algorithm>

namespace flange::host {

std::string sensor_flag_text(const SensorFlag& flag) {
  const std::string since = "flagged since " + flag.first_flagged.substr(0, 10);
  if (!flag.latched()) return since + ", not yet confirmed";
  return since + ", confirmed " + flag.confirmed.substr(0, 10);
}

bool clears_sensor_flag(const std::string& maintenance_kind) {
  return maintenance_kind != "odometer_reset";
}

std::optional<SensorFlag> next_sensor_flag(const std::optional<SensorFlag>& previous,
                                           bool flagged_now, const std::string& evaluated_at,
                                           const std::vector<MaintenanceMark>& maintenance) {
  std::optional<SensorFlag> flag = previous;
  if (flag) {
    const double first = day_of_iso_time(flag->first_flagged);
    const bool acted = std::any_of(maintenance.begin(), maintenance.end(), [&](const auto& m) {
      return clears_sensor_flag(m.kind) && m.day > first;
    });
    if (acted) flag.reset();
  }
  if (!flag) {
    if (!flagged_now) return std::nullopt;
    return SensorFlag{evaluated_at, ""};
  }
  if (flag->latched()) return flag;
  if (day_of_iso_time(evaluated_at) - day_of_iso_time(flag->first_flagged) < kFlagConfirmDays) {
    return flag;  // pending: the week is not over
  }
  if (!flagged_now) return std::nullopt;
  flag->confirmed = evaluated_at;
  return flag;
}

}  // namespace flange::host
