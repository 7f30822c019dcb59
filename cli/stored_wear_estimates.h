// SPDX-License-Identifier: MIT
// The wear estimates `flange wear` writes into the store after each estimate (Store::
// write_wear_estimates: what each wheel's reprofiling date at any risk is made from), and the
// plan made from them when they are current, so that a national fleet's plan does not read
// every run and re-run the estimator (docs/store.md, "At a national fleet's scale").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fleet_sensor_flags.h"
#include "fleet_wear.h"
#include "reprofiling_plan.h"
#include "store_records.h"
#include "thresholds.h"

namespace flange::cli {

// The estimate's per-wheel figures and settings, with the store's marks when its runs were read.
host::WearEstimateSet wear_estimate_set(const host::FleetWear& fleet, const host::StoreMarks& marks,
                                        const std::string& made_at);

// Why the stored estimates cannot stand for a new estimate: "" when they can (made with the same
// settings, and no run, maintenance event or calibration stored since).
std::string why_not_current(const std::optional<host::WearEstimateSet>& stored,
                            const host::StoreMarks& marks, const host::ThresholdConfig& thresholds);

// The sensor flags the stored estimates carry (none without them), for latch_sensor_flags. A
// flag whose dates are not times, or confirmed before it was first flagged, is refused
// (host::StoreError naming the store, the wheel and the field).
host::SensorFlags sensor_flags(const std::optional<host::WearEstimateSet>& stored,
                               const std::string& store_name);

// The plan's inputs of every stored wheel, as plan_input gives them from the estimate.
std::vector<host::PlanInput> plan_inputs(const host::WearEstimateSet& stored);

}  // namespace flange::cli
