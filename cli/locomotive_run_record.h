// SPDX-License-Identifier: MIT
// A run as the store keeps it, built the same way for `flange run --store` and the fleet
// scenario. Each wheel of a locomotive run: its static clearance at reference conditions
// (host/wear/axle_clearance.h: both wheels of an axle together over the instants both have,
// past the filter's start-up; a wheel without its axle partner takes its own median), its mean
// temperature past the start-up, counts, final alarm and errors against a reference; with the
// new flange's sensor gap known, its wear (clearance - gap). The reduced trace: per wheel, the
// means of the filtered clearance and the temperature over each kilometre of the run (the run's
// distance spread evenly over its time; one bin when the distance is not known), past the
// filter's start-up.
#pragma once

#include <optional>
#include <string>

#include "locomotive_run.h"
#include "run_pipeline.h"
#include "store_records.h"

namespace flange::cli {

// Appends one channel's reduced trace (axle 0 and side "" for a recording of no wheel) to
// `record`, binned over record.distance_km.
void add_reduced_trace(host::RunRecord& record, const host::RunSummary& summary,
                       const host::RunTrace& trace, int axle, const std::string& side);

// The run of `run`'s wheels (each channel's trace must be kept: run_locomotive's keep_trace):
// locomotive, distance, sample rate, counts, final alarm, wheels, alarm events and reduced
// trace. The caller adds when and how it ran (time, odometer, coefficients, calibration, engine,
// session, summary). `new_flange_gap_mm`: the clearance the sensor was set to over a new flange
// (mm, > 0); without it wear_mm stays empty.
host::RunRecord locomotive_run_record(const host::LocomotiveRun& run, const std::string& locomotive,
                                      double distance_km,
                                      std::optional<double> new_flange_gap_mm = std::nullopt);

}  // namespace flange::cli
