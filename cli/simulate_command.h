// SPDX-License-Identifier: MIT
// The `flange simulate` subcommand: a scenario through the sensor twin into a recording.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace flange::cli {

struct SimulateOptions {
  std::string scenario;              // bench, loco, fleet or fleet-alt
  std::vector<std::string> effects;  // NAME or NAME:key=value,...; one effect per argument
  std::optional<double> fs_hz;       // default: 6 Hz (bench), 100 Hz (loco)
  std::optional<double> duration_s;  // default: the scenario's own (6600 s bench, 300 s loco)
  std::optional<std::uint64_t> seed;  // required for bench and loco; fleet: 0 by default
  // bench: the recording; loco with --wheels above 1: a folder; fleet: the folder for the truth
  // file and the depot's bench calibration (default: the SQLite store's folder).
  std::optional<std::filesystem::path> out;
  std::optional<std::filesystem::path> twin;         // start from this twin file
  std::optional<std::filesystem::path> save_twin;    // write the twin used, effects included
  std::optional<std::filesystem::path> calibration;  // model.json as the nominal model
  // loco only: wheels 1 to 12 (channels 0..N-1: axle c/2 + 1, left then right). Above 1, out
  // is a folder that gets channel_XX.csv and locomotive.json (docs/locomotive.md).
  std::optional<int> wheels;
  // fleet only (docs/fleet.md): locomotives 1 to 100, days 1 to 3650, the store's URL.
  std::optional<int> locomotives;
  std::optional<int> days;
  std::optional<std::string> store;
};

// Registers the subcommand on `app`; the returned pointer tells whether it was chosen.
CLI::App* add_simulate_command(CLI::App& app, SimulateOptions& options);

// Runs a parsed simulate command. Returns 0; throws when a file cannot be written (1) and
// sim::BadArgument for a bad argument, effect or twin file (2; one line names it and its valid
// range). `command_line` goes into a locomotive's manifest as the command that made it.
int run_simulate_command(const SimulateOptions& options,
                         const std::vector<std::string>& command_line, std::ostream& out);

}  // namespace flange::cli
