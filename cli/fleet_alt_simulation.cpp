// SPDX-License-Identifier: MIT
#include "fleet_alt_simulation.h"

#include <fmt/format.h>

#include <ostream>
#include <stdexcept>

#include "cli.h"
#include "fleet_alt_folder.h"
#include "version.h"

namespace flange::cli {
namespace {

namespace alt = fleet_alt;

alt::FleetAltSettings fleet_alt_settings(const SimulateOptions& options) {
  for (const auto& [given, name] : {std::pair{options.wheels.has_value(), "--wheels"},
                                    {options.store.has_value(), "--store"},
                                    {!options.effects.empty(), "--effect"},
                                    {options.twin.has_value(), "--twin"},
                                    {options.save_twin.has_value(), "--save-twin"},
                                    {options.calibration.has_value(), "--calibration"}}) {
    if (given) {
      throw std::invalid_argument(fmt::format(
          "{}: the fleet-alt scenario has its own sensors and writes a folder for the service "
          "path; leave it out",
          name));
    }
  }
  if (!options.out) throw std::invalid_argument("--out is required: the folder to write");
  alt::FleetAltSettings settings;
  settings.locomotives = options.locomotives.value_or(settings.locomotives);
  settings.days = options.days.value_or(settings.days);
  settings.seed = options.seed.value_or(0);
  settings.recording_s = options.duration_s.value_or(settings.recording_s);
  settings.fs_hz = options.fs_hz.value_or(settings.fs_hz);
  return settings;
}

void print_written(const alt::FleetAltTruth& truth, const alt::FleetAltWritten& written,
                   const std::filesystem::path& dir, std::ostream& out) {
  out << fmt::format(
      "  {} locomotive-days recorded, {} missing (ran without a recording), {} depot days; "
      "{} axles reprofiled\n",
      written.runs, written.missing_days, written.depot_days, written.reprofilings);
  for (const alt::DepotEvent& event : truth.events) {
    if (event.kind == alt::DepotEventKind::kReprofile) continue;
    out << fmt::format("  {} {}: {}", alt::date_text(truth.settings.start_day + event.day),
                       truth.locomotives[static_cast<std::size_t>(event.locomotive)].name,
                       alt::depot_event_name(event.kind));
    if (event.axle > 0) out << fmt::format(" axle {}", event.axle);
    if (event.from_axle > 0) out << fmt::format(" from axle {}", event.from_axle);
    out << "\n";
  }
  const alt::DriftTruth& drift = truth.drift;
  out << fmt::format("  drifting sensor: {} axle {} {} from {} at {:+.4f} V/day\n",
                     truth.locomotives[static_cast<std::size_t>(drift.locomotive)].name,
                     drift.channel / 2 + 1, drift.channel % 2 == 0 ? "left" : "right",
                     alt::date_text(truth.settings.start_day + drift.start_day),
                     drift.rate_v_per_day);
  out << "  wrote " << dir.string()
      << "/: bench/, days/, runs.csv, maintenance.csv and fleet_truth.json\n";
}

}  // namespace

int run_fleet_alt_simulation(const SimulateOptions& options,
                             const std::vector<std::string>& command_line, std::ostream& out) {
  const alt::FleetAltTruth truth = alt::plan_fleet_alt(fleet_alt_settings(options));
  const alt::FleetAltSettings& s = truth.settings;
  out << fmt::format(
      "simulate: fleet-alt scenario, {} locomotives x {} days from {}, seed {}; each recorded "
      "day {} s of 12 wheels at {} Hz\n",
      s.locomotives, s.days, alt::date_text(s.start_day), s.seed, s.recording_s, s.fs_hz);
  const alt::FleetAltWritten written =
      alt::write_fleet_alt_folder(truth, *options.out, runtime::generated_by(command_line));
  print_written(truth, written, *options.out, out);
  return kExitOk;
}

}  // namespace flange::cli
