// SPDX-License-Identifier: MIT
// `flange maintenance`: what the depot did to a locomotive, written into the store, so that
// `flange run --store` and `flange wear` read each wheel's runs in the light of it
// (docs/store.md, "Maintenance events"):
//   reprofile        a lathe pass of an axle (--axle; both wheels unless --side): a new flange,
//                    whose reference clearance is the wheel's first run after it
//   wheelset_moved   the wheelset now on --axle ran on --from-axle before: its wear goes with it
//   sensor_replaced  a new sensor on one wheel (--axle, --side, --sensor SERIAL): the wear
//                    carries over the step of the new unit
//   odometer_reset   the locomotive's odometer was reset (--odometer-km: its reading before the
//                    reset); every later run's odometer is counted on from that reading
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace flange::cli {

struct MaintenanceOptions {
  std::string store;                  // sqlite:PATH or postgresql://...
  std::string locomotive;             // the locomotive's name
  std::string kind;                   // one of the four above
  std::string at;                     // when, UTC
  std::optional<int> axle;            // 1 to 6
  std::optional<std::string> side;    // left or right
  std::optional<int> from_axle;       // wheelset_moved: 1 to 6, not --axle
  std::optional<double> odometer_km;  // the odometer then (odometer_reset: before the reset)
  std::string sensor;                 // sensor_replaced: the new unit's serial
  std::string note;                   // free text, stored as given
};

CLI::App* add_maintenance_command(CLI::App& app, MaintenanceOptions& options);

// Returns 0; throws host::StoreError when the store cannot be written (1) and host::InputError
// or host::StoreUrlError for a bad argument (2: one line naming it).
int run_maintenance_command(const MaintenanceOptions& options, std::ostream& out);

}  // namespace flange::cli
