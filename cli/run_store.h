// SPDX-License-Identifier: MIT
// `flange run --store`: a run as the store keeps it. One recording becomes a service session
// and a run (its summary, alarm events and reduced trace, no wheel rows); a locomotive manifest
// also gives each wheel's figures, built as the fleet scenario builds them
// (locomotive_run_record.h): each wheel's clearance at reference conditions and its wear, read
// with the depot's maintenance records (wheel_wear_reference.h), and the odometer counted on over
// recorded resets.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "locomotive_run.h"
#include "run_pipeline.h"
#include "store.h"

namespace flange::cli {

struct RunStoreOptions {
  std::optional<std::string> url;         // sqlite:PATH or postgresql://...
  std::string locomotive;                 // manifest: "" = the manifest's folder name
  std::optional<std::string> started_at;  // UTC; now when not given
  double distance_km = 0.0;               // this run's distance (0: not known)
  double odometer_km = 0.0;               // the locomotive's odometer at the run's end
  // manifest: the clearance over a new flange (mm, > 0); default the alarm settings' sensor gap.
  std::optional<double> new_flange_clearance_mm;
};

// Both throw StoreError (exit status 1) and return the run's id; store_locomotive_run throws
// InputError (exit status 2) for an odometer that runs backwards without a recorded reset.
std::int64_t store_recording_run(host::Store& store, const RunStoreOptions& options,
                                 const host::RunOptions& run, const host::RunSummary& summary,
                                 const host::RunTrace& trace);
std::int64_t store_locomotive_run(host::Store& store, const RunStoreOptions& options,
                                  const host::LocomotiveRun& run);

}  // namespace flange::cli
