// SPDX-License-Identifier: MIT
#include "maintenance_command.h"

#include <fmt/format.h>

#include <ostream>

#include "cli.h"
#include "input_error.h"
#include "store.h"
#include "utc_time.h"

namespace flange::cli {
namespace {

using host::InputError;

// The wheels the event names, checked against its kind.
std::vector<host::WheelKey> event_wheels(const MaintenanceOptions& o) {
  const bool whole = o.kind == "odometer_reset";
  if (whole && (o.axle || o.side)) {
    throw InputError("--axle/--side: an odometer reset is the whole locomotive's; leave them out");
  }
  if (!whole && !o.axle) throw InputError("--axle is required with --kind " + o.kind + ": 1 to 6");
  if (o.kind == "sensor_replaced" && !o.side) {
    throw InputError("--side is required with --kind sensor_replaced: left or right");
  }
  if (o.kind == "wheelset_moved" && (!o.from_axle || *o.from_axle == *o.axle)) {
    throw InputError("--from-axle is required with --kind wheelset_moved: 1 to 6, not --axle");
  }
  if (o.kind != "wheelset_moved" && o.from_axle) {
    throw InputError("--from-axle: only --kind wheelset_moved takes it");
  }
  if (whole && !o.odometer_km) {
    throw InputError(
        "--odometer-km is required with --kind odometer_reset: its reading before "
        "the reset, 0 to 1e8 km");
  }
  std::vector<host::WheelKey> wheels;
  for (int axle = 1; axle <= 6; ++axle) {
    if (!whole && axle != *o.axle) continue;
    for (const char* side : {"left", "right"}) {
      if (o.side && *o.side != side) continue;
      wheels.push_back({o.locomotive, axle, side});
    }
  }
  return wheels;
}

}  // namespace

CLI::App* add_maintenance_command(CLI::App& app, MaintenanceOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "maintenance",
      "Record what the depot did to a locomotive (a lathe pass, a wheelset moved, a "
      "sensor replaced, an odometer reset) in the store");
  cmd->add_option("--store", options.store, "sqlite:PATH or postgresql://...")->required();
  cmd->add_option("--locomotive", options.locomotive, "the locomotive's name")->required();
  cmd->add_option("--kind", options.kind,
                  "reprofile, wheelset_moved, sensor_replaced or odometer_reset")
      ->required()
      ->check(CLI::IsMember({"reprofile", "wheelset_moved", "sensor_replaced", "odometer_reset"}));
  cmd->add_option("--at", options.at, "when, UTC (YYYY-MM-DDThh:mm:ssZ)")->required();
  cmd->add_option("--axle", options.axle, "the axle, 1 (leading) to 6")->check(CLI::Range(1, 6));
  cmd->add_option("--side", options.side, "one wheel of the axle: left or right (default both)")
      ->check(CLI::IsMember({"left", "right"}));
  cmd->add_option("--from-axle", options.from_axle,
                  "wheelset_moved: the axle it ran on before, 1 to 6")
      ->check(CLI::Range(1, 6));
  cmd->add_option("--odometer-km", options.odometer_km,
                  "the odometer reading then (odometer_reset: before the reset), 0 to 1e8 km")
      ->check(CLI::Range(0.0, 1e8));
  cmd->add_option("--sensor", options.sensor, "sensor_replaced: the new sensor's serial");
  cmd->add_option("--note", options.note, "free text");
  return cmd;
}

int run_maintenance_command(const MaintenanceOptions& options, std::ostream& out) {
  const std::vector<host::WheelKey> wheels = event_wheels(options);
  const std::string at = format_utc_time(parse_utc_time(options.at, "--at"));
  const std::unique_ptr<host::Store> store = host::open_store(options.store);
  for (const host::WheelKey& wheel : wheels) {
    host::MaintenanceRecord event;
    event.wheel = wheel;
    event.at = at;
    event.odometer_km = options.odometer_km.value_or(0.0);
    event.kind = options.kind;
    event.note = options.note;
    event.from_axle = options.from_axle;
    store->record_maintenance(event);
    if (options.kind == "sensor_replaced" && !options.sensor.empty()) {
      store->upsert_sensor({options.sensor, "", wheel, at});
    }
  }
  out << fmt::format("maintenance: {} of {} at {} recorded on {} wheel(s) in {}\n", options.kind,
                     options.locomotive, at, wheels.size(), store->name());
  return kExitOk;
}

}  // namespace flange::cli
