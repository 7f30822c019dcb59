// SPDX-License-Identifier: MIT
// `flange calibrate`: fit (and refit, as sessions are appended) the temperature-compensating
// regression from a calibration database, a CSV file or the bench sessions of a store.
#pragma once

#include <CLI/CLI.hpp>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "regression.h"

namespace flange::cli {

struct CalibrateOptions {
  std::string data;                   // the calibration database (recording format)
  std::optional<std::string> append;  // a new session to add to it first
  std::optional<std::string> store;   // sqlite:PATH or postgresql://...: import, refit from it
  std::string sensor;                 // the sensor the sessions calibrate (store only; "" none)
  std::string out;                    // model.json
  host::RegressionOptions regression;
};

CLI::App* add_calibrate_command(CLI::App& app, CalibrateOptions& options);
// Returns 0; throws host::InputError or host::StoreUrlError for a bad input (2), and
// host::StoreError or std::runtime_error when the store or --out cannot be written (1).
int run_calibrate_command(const CalibrateOptions& options,
                          const std::vector<std::string>& command_line, std::ostream& out);

}  // namespace flange::cli
