// SPDX-License-Identifier: MIT
// The fleet table's per-wheel sums, kept up to date in the writes' own transactions (schema
// version 3, table `wheel_fit`): the run count, the latest run, and since the wheel's latest
// maintenance event the least-squares sums of wear against odometer, and the alarm count. The
// fleet table then reads one row per wheel, whatever the history's length, instead of
// aggregating every wheel row (at 1,000 locomotives x a year: 12,000 rows against 4.4 million).
// Each update is set-based SQL over the batch just written; both backends run the same text.
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

// Adds the wheel rows and alarm events of runs `run_ids` (written in this transaction) to their
// wheels' sums; runs at or after a wheel's latest maintenance count in its fit.
void add_runs_to_wheel_fit(soci::session& sql, StoreBackend backend,
                           const std::vector<long long>& run_ids);

// After a maintenance event on `wheel_id`: its fit restarts from its latest event (recomputed
// from the runs since).
void refit_wheel_since_maintenance(soci::session& sql, long long wheel_id);

}  // namespace flange::host
