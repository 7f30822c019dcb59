// SPDX-License-Identifier: MIT
// `flange run --store`: a run as the store keeps it. One recording becomes a service session
// and a run (its summary, alarm events and reduced trace, no wheel rows); a locomotive manifest
// also gives each wheel's figures, built as the fleet scenario builds them
// (locomotive_run_record.h): each wheel's clearance at reference conditions, wear_mm left empty.
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
};

// Both throw StoreError (exit status 1) and return the run's id.
std::int64_t store_recording_run(host::Store& store, const RunStoreOptions& options,
                                 const host::RunOptions& run, const host::RunSummary& summary,
                                 const host::RunTrace& trace);
std::int64_t store_locomotive_run(host::Store& store, const RunStoreOptions& options,
                                  const host::LocomotiveRun& run);

}  // namespace flange::cli
