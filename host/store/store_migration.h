// SPDX-License-Identifier: MIT
// The schema version this flange writes, and a store opened at an older one (for tests of the
// migration: open_store then brings it up to date).
#pragma once

#include <memory>
#include <string>

#include "store.h"

namespace flange::host {

inline constexpr int kStoreSchemaVersion = 7;

// The version whose maintenance events carry a wheelset move's source axle as a column
// (from_axle); an older one holds it only in the event's note, "from axle N[; note]".
inline constexpr int kFromAxleSchemaVersion = 5;

// The version whose wear estimates carry each wheel's sensor flag (sensor_flag_first,
// sensor_flag_confirmed).
inline constexpr int kSensorFlagSchemaVersion = 6;

// The version whose wear estimates carry the dates' whole forecast input for the plan (forecast,
// JSON); an older one's estimates are planned on the rate's quantile alone.
inline constexpr int kForecastSchemaVersion = 7;

// Like open_store, but creates or migrates the schema only up to `version` (1 to
// kStoreSchemaVersion). A store already past `version` is refused as newer.
std::unique_ptr<Store> open_store_at_schema_version(const std::string& url, int version);

}  // namespace flange::host
