// SPDX-License-Identifier: MIT
// Records the store tests write: a locomotive run of 12 wheels with alarm events and a trace.
#pragma once

#include <string>

#include "store_records.h"

namespace flange::testing {

// Day `day` (0-based) of 2026-01: "2026-01-DDT06:00:00Z" plus `hour` hours.
std::string test_time(int day, int hour = 0);

// A run of `locomotive` whose 12 wheels have worn `wear_mm` + 0.01 * channel, one warning on
// axle 1 left and a trace of three kilometres per wheel.
host::RunRecord test_run(const std::string& locomotive, const std::string& started_at,
                         double odometer_km, double wear_mm);

}  // namespace flange::testing
