// SPDX-License-Identifier: MIT
#include "run_command.h"

#include <ostream>

#include "cli.h"
#include "input_error.h"
#include "locomotive_manifest.h"
#include "locomotive_report.h"
#include "locomotive_run.h"
#include "locomotive_summary.h"
#include "run_report.h"
#include "store.h"
#include "version.h"

namespace flange::cli {

namespace {

// The store is opened before the run: a store that cannot be reached stops it early.
std::unique_ptr<host::Store> open_run_store(const RunStoreOptions& options) {
  if (!options.url) return nullptr;
  return host::open_store(*options.url);
}

void say_stored(const host::Store& store, std::int64_t run_id, std::ostream& out) {
  out << "  stored as run " << run_id << " in " << store.name() << "\n";
}

int run_recording(const RunCommandOptions& command, std::ostream& out) {
  const host::RunOptions& options = command.run;
  const std::unique_ptr<host::Store> store = open_run_store(command.store);
  host::RunTrace trace;
  const host::RunSummary summary =
      host::run_pipeline(options, options.report_dir || store ? &trace : nullptr);
  out << run_summary_text(options, summary);
  if (options.out_csv) out << "  wrote " << *options.out_csv << "\n";
  if (options.report_dir) {
    write_run_report(*options.report_dir, options, summary, trace);
    out << "  report " << *options.report_dir << "/index.html\n";
  }
  if (store) {
    say_stored(*store, store_recording_run(*store, command.store, options, summary, trace), out);
  }
  return summary.rtl_mismatches > 0 ? kExitFailure : kExitOk;
}

// Every channel of a manifest; with --out DIR, its CSVs, summary.json and report go there.
int run_manifest(const RunCommandOptions& options, const std::vector<std::string>& command_line,
                 std::ostream& out) {
  if (options.run.report_dir) {
    throw host::InputError("--report: with --manifest the report goes into the --out folder");
  }
  const host::LocomotiveManifest manifest = host::load_locomotive_manifest(*options.manifest);
  const std::unique_ptr<host::Store> store = open_run_store(options.store);
  std::optional<std::filesystem::path> out_dir;
  if (options.run.out_csv) out_dir = *options.run.out_csv;
  const host::LocomotiveRun run =
      host::run_locomotive(manifest, options.run, out_dir, store != nullptr);
  out << host::locomotive_table_text(run);
  if (out_dir) {
    host::write_locomotive_summary_json(*out_dir / "summary.json", run,
                                        runtime::generated_by(command_line));
    host::write_locomotive_report(*out_dir, run);
    out << "  wrote " << out_dir->string() << "/channel_XX.csv, summary.json and index.html\n";
  }
  if (store) say_stored(*store, store_locomotive_run(*store, options.store, run), out);
  for (const host::ChannelRun& channel : run.channels) {
    if (channel.summary.rtl_mismatches > 0) return kExitFailure;
  }
  return kExitOk;
}

void add_run_store_options(CLI::App& cmd, RunStoreOptions& store, CLI::Option* manifest) {
  CLI::Option* url = cmd.add_option(
      "--store", store.url,
      "sqlite:PATH or postgresql://...: keep the run there (its session, summary, wheels, "
      "alarm events and a per-kilometre trace; docs/store.md)");
  cmd.add_option("--locomotive", store.locomotive,
                 "with --store and --manifest: the locomotive's name (default: the manifest's "
                 "folder name)")
      ->needs(url)
      ->needs(manifest);
  cmd.add_option("--started-at", store.started_at,
                 "with --store: when the run started, UTC (YYYY-MM-DDThh:mm:ssZ; default now)")
      ->needs(url);
  cmd.add_option("--distance-km", store.distance_km,
                 "with --store: the run's distance in km (0: not known, one trace bin)")
      ->needs(url)
      ->check(CLI::Range(0.0, 1e5));
  cmd.add_option("--odometer-km", store.odometer_km,
                 "with --store: the locomotive's odometer at the end of the run, km (as read: a "
                 "reset recorded with flange maintenance is counted on from)")
      ->needs(url)
      ->check(CLI::Range(0.0, 1e8));
  cmd.add_option("--new-flange-clearance-mm", store.new_flange_clearance_mm,
                 "with --store and --manifest: each wheel's clearance over a new flange, the "
                 "reference of its wear until the depot records a change (default: the sensor "
                 "gap of the alarm settings, 2 mm)")
      ->needs(url)
      ->needs(manifest)
      ->check(CLI::Range(0.1, 10.0));
}

}  // namespace

CLI::App* add_run_command(CLI::App& app, RunCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "run", "Run a recording through regression, the IIR filter and the wear thresholds");
  host::RunOptions& run = options.run;
  CLI::Option* input =
      cmd->add_option("--input", run.input, "recording CSV (t_s,clearance_mm,temp_c,voltage_v)");
  CLI::Option* manifest = cmd->add_option(
      "--manifest", options.manifest,
      "locomotive.json: run every channel it names, each alone (docs/locomotive.md)");
  input->excludes(manifest);
  cmd->add_option("--calibration", run.calibration, "model.json from flange calibrate")->required();
  cmd->add_option("--coeffs", run.coeffs, "filter.json from flange design")->required();
  cmd->add_option("--engine", run.engine,
                  "model: bit-accurate model; rtl: Verilated RTL checked by the model; float: "
                  "double-precision design")
      ->check(CLI::IsMember({"model", "rtl", "float"}))
      ->default_str("model");
  cmd->add_option("--channel", run.channel,
                  "with --input and a multichannel set: the core channel to filter on (its own "
                  "coefficient set, if it has one); --manifest uses each entry's channel")
      ->default_val(0)
      ->excludes(manifest);
  cmd->add_option("--out", run.out_csv,
                  "output CSV: t_s,clearance_raw_mm,clearance_filt_mm,flange_mm,alarm,flags; with "
                  "--manifest a folder for channel_XX.csv, summary.json and the report");
  cmd->add_option("--report", run.report_dir, "folder for the HTML report");
  cmd->add_flag("--lenient", run.lenient,
                "flag bad rows (the filter holds its last input) instead of stopping");
  cmd->add_option("--threads", run.threads,
                  "1: read, filter and write on one thread; 2: read the recording ahead and "
                  "write the output CSV behind on threads of their own (the same output); 0: 2 "
                  "for a recording over 1 MiB")
      ->check(CLI::Range(0, 2))
      ->default_val(0);
  add_run_store_options(*cmd, options.store, manifest);
  host::ThresholdConfig& t = run.thresholds;
  cmd->add_option("--warning-mm", t.warning_clearance_mm, "warning clearance (mm)")
      ->default_val(t.warning_clearance_mm);
  cmd->add_option("--critical-flange-mm", t.critical_flange_mm, "critical flange thickness (mm)")
      ->default_val(t.critical_flange_mm);
  cmd->add_option("--hysteresis-mm", t.hysteresis_mm, "alarm hysteresis (mm)")
      ->default_val(t.hysteresis_mm);
  cmd->add_option("--dwell-s", t.min_dwell_s, "time a condition must hold to change an alarm")
      ->default_val(t.min_dwell_s);
  cmd->add_option("--max-step-mm", t.max_step_mm, "h of eq. 3.38: largest wear between windows")
      ->default_val(t.max_step_mm);
  cmd->add_option("--step-window-s", t.step_window_s, "window of one wear measurement (s)")
      ->default_val(t.step_window_s);
  return cmd;
}

int run_run_command(const RunCommandOptions& options, const std::vector<std::string>& command_line,
                    std::ostream& out) {
  if (options.manifest) return run_manifest(options, command_line, out);
  if (options.run.input.empty()) {
    throw host::InputError("--input REC.csv or --manifest locomotive.json is required");
  }
  return run_recording(options, out);
}

}  // namespace flange::cli
