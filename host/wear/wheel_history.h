// SPDX-License-Identifier: MIT
// What `flange wear` knows of a wheel: its runs in time order (when, at which odometer reading,
// the static clearance at reference conditions) and the depot's recorded maintenance.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace flange::host {

struct WheelId {
  std::string locomotive;
  int axle = 1;               // 1 (leading) to 6
  std::string side = "left";  // "left" or "right"
  int channel = 0;            // 0 to 11
  bool operator==(const WheelId&) const = default;
};

struct WearObservation {
  std::int64_t run_id = 0;
  std::string at;             // the run's start, ISO 8601 UTC
  double day = 0.0;           // the same, in days since 1970-01-01
  double odometer_km = 0.0;   // the locomotive's odometer at the run
  double clearance_mm = 0.0;  // static clearance at reference conditions (axle_clearance.h)
};

struct MaintenanceMark {
  std::string at;  // ISO 8601 UTC
  double day = 0.0;
  double odometer_km = 0.0;
  // "reprofile" resets the flange; "sensor_replaced" and "wheelset_moved" start a new segment
  // (another unit's offset, another flange) without a reprofiling; other kinds are listed only.
  std::string kind;
};

struct WheelHistory {
  WheelId wheel;
  std::vector<WearObservation> runs;         // time order
  std::vector<MaintenanceMark> maintenance;  // time order
};

// Days since 1970-01-01 of an ISO 8601 UTC time "YYYY-MM-DD[Thh:mm[:ss[.f]]][Z]". Throws
// std::invalid_argument naming the text when it is not one.
double day_of_iso_time(const std::string& text);

}  // namespace flange::host
