// SPDX-License-Identifier: MIT
// A sensor fault that stays raised until the depot acts. The drift search (sensor_drift.h) runs
// on a wheel's whole history at every estimate, and what it flags can come and go: a drift
// flagged a few weeks after its start can be lost months later, when other axles' wander raises
// the locomotive's bar, and a healthy sensor's wander can be flagged for a week and not the next.
// A depot expects an alarm, once raised, to stay until it has acted, so a flag is latched; and
// so that a passing wander is not latched for good, a flag is latched only when the search
// still flags the sensor at an estimate at least kFlagConfirmDays after the one that first
// flagged it (dates of the wheel's last run: days of data, not of calendar). A latched flag is
// cleared by any maintenance event on the wheel after it was first flagged (a sensor replaced,
// a lathe pass with its sensor checked, a wheelset moved), except an odometer reset, which
// touches no wheel; if the search flags the sensor again after that, it is a new flag,
// confirmed anew.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "wheel_history.h"

namespace flange::host {

// Days of data between the estimate that first flags a sensor and the one that confirms it. A
// healthy sensor's wander on the second fleet reality is often flagged for a week or two and
// then not: on its development fleets (weekly estimates, bench/wear_drift_delay.sh) a week's
// confirmation latches 28 of 590 healthy sensors at some time, two weeks' 23, and every drift is
// latched with either; two weeks delay the latch, not the flag (the search's own flag shows
// from the first estimate).
inline constexpr double kFlagConfirmDays = 14.0;

struct SensorFlag {
  std::string first_flagged;  // the wheel's last run at the estimate that first flagged it
  std::string confirmed;      // the same at the estimate that confirmed it; "" while pending
  bool latched() const { return !confirmed.empty(); }
  bool operator==(const SensorFlag&) const = default;
};

// The wheel's flag after an estimate: `previous` as the store kept it, `flagged_now` whether
// this estimate's drift search flags the sensor, `evaluated_at` the wheel's last run (ISO 8601
// UTC), `maintenance` the wheel's recorded events. Pending: kept until an estimate at least
// kFlagConfirmDays later, which confirms it when it still flags the sensor and drops it when
// not. Latched: kept whatever the search says, until a maintenance event clears it.
std::optional<SensorFlag> next_sensor_flag(const std::optional<SensorFlag>& previous,
                                           bool flagged_now, const std::string& evaluated_at,
                                           const std::vector<MaintenanceMark>& maintenance);

// "flagged since DATE, confirmed DATE" (latched) or "flagged since DATE, not yet confirmed".
std::string sensor_flag_text(const SensorFlag& flag);

// Whether a maintenance event of this kind clears a wheel's sensor flag (all but an odometer
// reset).
bool clears_sensor_flag(const std::string& maintenance_kind);

}  // namespace flange::host
