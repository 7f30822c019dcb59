// SPDX-License-Identifier: MIT
// `flange design`: the command line of coeffs/ (a Butterworth low-pass from a spec, quantised
// for the core): options, validation, outputs, exit status.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "generator.h"

namespace flange::cli {

struct DesignOptions {
  int channels = 1;  // --channels: channels sharing the core, one set for all
  std::vector<double> channel_fc_hz;  // --channel-fc: a set per channel, one cut-off each
  coeffs::DesignRequest request;
  std::string structure = "sos";
  std::optional<std::filesystem::path> out_dir;  // nothing is written without it
  bool no_plot = false;
};

// Registers the subcommand on `app`; the returned pointer tells whether it was chosen.
CLI::App* add_design_command(CLI::App& app, DesignOptions& options);

// Runs a parsed design command. `command_line` is how the command was given, recorded in every
// generated file without its --out. Returns 0; throws coeffs::BadArgument for a bad argument (2)
// and coeffs::DesignRejected for a design that would not work in hardware (3).
int run_design_command(const DesignOptions& options, const std::vector<std::string>& command_line,
                       std::ostream& out);

// "flange design ..." with any --out argument left out, so that a set regenerated elsewhere is
// byte-identical.
std::string command_without_out(const std::vector<std::string>& command_line);

}  // namespace flange::cli
