// SPDX-License-Identifier: MIT
#include "diagnose_command.h"

#include <fmt/format.h>

#include <exception>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "cli.h"
#include "diagnose_memory.h"
#include "diagnose_report.h"
#include "improved_twin_report.h"
#include "input_error.h"
#include "parallel_work.h"
#include "separate_sessions.h"
#include "sim_error.h"
#include "twin_file.h"
#include "utc_time.h"

namespace flange::cli {

CLI::App* add_diagnose_command(CLI::App& app, DiagnoseCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "diagnose",
      "Where the sim-to-real gap of a recording lies, which effect causes it, and how "
      "far it shrinks on held-out data");
  cmd->add_option("--real", options.real, "recording (CSV t_s,clearance_mm,temp_c,voltage_v)");
  CLI::Option* holdout =
      cmd->add_option("--holdout", options.holdout, "a separate held-out recording");
  cmd->add_option("--holdout-fraction", options.holdout_fraction,
                  "hold out the last fraction of --real instead, 0.05 to 0.5")
      ->excludes(holdout)
      ->check(CLI::Range(0.05, 0.5));
  CLI::Option* real_start = cmd->add_option(
      "--real-start", options.real_start,
      "when --real's t_s = 0 was, UTC (2026-11-21T09:30:00Z); with --holdout-start it carries "
      "the sensor's age from one session to the other");
  cmd->add_option("--holdout-start", options.holdout_start,
                  "when --holdout's t_s = 0 was, UTC; needs --real-start")
      ->needs(holdout)
      ->needs(real_start);
  real_start->needs(holdout);
  cmd->add_option("--twin", options.twin, "twin file (JSON); default: thesis eq. 3.14");
  cmd->add_option("--out", options.out, "folder for diagnosis.json, report.html and twin.json");
  cmd->add_option("--seed", options.seed, "seed of the bootstrap resampling")->default_val(1);
  cmd->add_option("--bootstrap", options.bootstrap_rounds, "bootstrap rounds, 20 to 2000")
      ->default_val(100)
      ->check(CLI::Range(20, 2000));
  return cmd;
}

int run_diagnose_command(const DiagnoseCommandOptions& options, std::ostream& out) {
  if (options.real.empty())
    throw host::InputError(
        "--real: a recording is required (or --hw --coeffs DIR/filter.json for the float design "
        "against the RTL)");
  if (options.out.empty()) throw host::InputError("--out: an output folder is required");
  if (!options.holdout && !options.holdout_fraction) {
    throw host::InputError("give --holdout B.csv or --holdout-fraction F (0.05 to 0.5)");
  }
  keep_freed_memory_for_reuse();
  diagnose::DiagnoseOptions diagnose_options;
  if (options.twin) diagnose_options.twin = sim::load_twin(*options.twin);
  diagnose_options.seed = options.seed;
  diagnose_options.bootstrap_rounds = options.bootstrap_rounds;

  if (options.real_start.has_value() != options.holdout_start.has_value()) {
    throw host::InputError("--real-start and --holdout-start go together: give both or neither");
  }
  // The two recordings read at once where a thread is free (a 45-minute 100 Hz file takes about
  // 0.1 s); a failure of --real is reported before one of --holdout, as when read in turn.
  diagnose::RecordingSeries real, heldout;
  std::exception_ptr real_failed, heldout_failed;
  diagnose::run_both(
      [&] {
        try {
          real = diagnose::read_recording_series(options.real);
        } catch (...) {
          real_failed = std::current_exception();
        }
      },
      [&] {
        try {
          if (options.holdout) heldout = diagnose::read_recording_series(*options.holdout);
        } catch (...) {
          heldout_failed = std::current_exception();
        }
      });
  if (real_failed) std::rethrow_exception(real_failed);
  if (options.real_start) real.start_utc_s = parse_utc_time(*options.real_start, "--real-start");
  diagnose::HoldoutSplit split;
  if (options.holdout) {
    split.calibration = real;
    if (heldout_failed) std::rethrow_exception(heldout_failed);
    split.heldout = std::move(heldout);
    if (options.holdout_start) {
      split.heldout.start_utc_s = parse_utc_time(*options.holdout_start, "--holdout-start");
    }
    split.heldout_name = *options.holdout;
    diagnose::check_separate_sessions(split.calibration, split.heldout);
  } else {
    split = diagnose::split_holdout(real, *options.holdout_fraction);
  }
  const diagnose::DiagnosisResult result =
      diagnose::diagnose_in_detail(split.calibration, split.heldout, diagnose_options);

  std::filesystem::create_directories(options.out);
  const std::filesystem::path json_path = std::filesystem::path(options.out) / "diagnosis.json";
  std::ofstream json(json_path, std::ios::binary);
  json << diagnose::diagnosis_json(result, options.real, split.heldout_name).dump(2) << "\n";
  json.close();
  if (!json) throw std::runtime_error(json_path.string() + ": cannot write");
  const std::filesystem::path twin_path =
      std::filesystem::path(options.out) / diagnose::kImprovedTwinFile;
  sim::save_twin(result.improved_twin.twin, twin_path);
  diagnose::write_diagnosis_report(options.out, result, options.real);
  out << diagnose::diagnosis_summary(result);
  out << "  wrote " << json_path.string() << ", "
      << (std::filesystem::path(options.out) / "report.html").string() << " and "
      << twin_path.string() << "\n";
  return kExitOk;
}

}  // namespace flange::cli
