// SPDX-License-Identifier: MIT
// Records the store tests write: a locomotive run of 12 wheels with alarm events and a trace.
#pragma once

#include <string>

#include "store.h"
#include "store_records.h"

namespace flange::testing {

// Day `day` (0-based) of 2026-01: "2026-01-DDT06:00:00Z" plus `hour` hours.
std::string test_time(int day, int hour = 0);

// A run of `locomotive` whose 12 wheels have worn `wear_mm` + 0.01 * channel, one warning on
// axle 1 left and a trace of three kilometres per wheel.
host::RunRecord test_run(const std::string& locomotive, const std::string& started_at,
                         double odometer_km, double wear_mm);

// Two locomotives' runs written every way the store takes them: one by one out of time order, in
// batches, a run tied in time with another, a wheel without a wear figure in one run, a wheel
// with no runs, maintenance before a wheel's runs, between them and backdated.
void write_mixed_history(host::Store& store);

// The fleet table's figures recomputed from every wheel's history, its maintenance events and
// alarm events, checked against `store.fleet_table()` (what the writes kept).
void expect_fleet_table_matches_runs(host::Store& store);

}  // namespace flange::testing
