// SPDX-License-Identifier: MIT
// The fleet table's per-wheel sums, kept up to date in the writes' own transactions (schema
// version 3, table `wheel_fit`): the run count, the latest run, and since the wheel's latest
// maintenance event the least-squares sums of wear against odometer, and the alarm count. The
// fleet table then reads one row per wheel, whatever the history's length, instead of
// aggregating every wheel row (at 1,000 locomotives x a year: 12,000 rows against 4.4 million).
// A batch of runs adds its own sums (wheel_fit_batch.h); the migration and a maintenance event
// recompute them with set-based SQL over the stored rows, the same text on both backends.
#pragma once

#include <soci/soci.h>

#include <string>
#include <vector>

#include "store_url.h"

namespace flange::host {

// The schema version that brought `wheel_fit`: a store opened at an older one (tests of the
// migration) is written without it.
inline constexpr int kWheelFitSchemaVersion = 3;

// The statements that create `wheel_fit` and fill it from the rows already stored (migration 3);
// {real} as in store_schema.cpp.
std::vector<std::string> wheel_fit_migration();

// After a maintenance event on `wheel_id`: its fit restarts from its latest event (recomputed
// from the runs since).
void refit_wheel_since_maintenance(soci::session& sql, long long wheel_id);

}  // namespace flange::host
