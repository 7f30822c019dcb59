// SPDX-License-Identifier: MIT
#include "calibrate_command.h"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "bench_store.h"
#include "calibration.h"
#include "cli.h"
#include "input_error.h"
#include "store.h"
#include "utc_time.h"
#include "version.h"

namespace flange::cli {

using host::CalibratedRange;
using host::Calibration;
using host::InputError;
using host::OrderCandidate;

namespace {

double now_utc_s() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

void print_calibration(const Calibration& calibration, std::ostream& out) {
  const CalibratedRange& r = calibration.range;
  out << fmt::format(
      "calibration: {} rows in {} ({} run{}), {} with a reference; V {:.3f}-{:.3f} V, "
      "T {:.1f}-{:.1f} C, d {:.3f}-{:.3f} mm\n",
      calibration.rows, calibration.database, calibration.runs.size(),
      calibration.runs.size() == 1 ? "" : "s",
      calibration.rows - calibration.rows_without_reference, r.v_min, r.v_max, r.t_min, r.t_max,
      r.d_min, r.d_max);
  out << "  order terms       r  adj_r2  rmse_mm   mae_mm  heldout_mae_mm\n";
  for (const OrderCandidate& c : calibration.fit.candidates) {
    out << fmt::format("  {:>5} {:>5} {:>7.4f} {:>7.4f} {:>8.4f} {:>8.4f} {:>15.4f}{}\n", c.order,
                       c.terms, c.stats.r, c.stats.adjusted_r2, c.stats.rmse_mm, c.stats.mae_mm,
                       c.stats.heldout_mae_mm,
                       c.order == calibration.fit.model.order() ? "  <- selected" : "");
  }
  out << "  selected: " << calibration.fit.selection << "\n";
  out << "  d = " << calibration.fit.model.equation() << "   (d mm, V volts, T deg C)\n";
}

// The CSV database (or the appended session alone, without --data) into the store, then the
// fit from every bench session the store holds.
Calibration calibrate_from_store(const CalibrateOptions& options,
                                 std::unique_ptr<host::Store>& store,
                                 std::vector<std::int64_t>& session_ids, std::ostream& out) {
  store = host::open_store(*options.store);
  const std::string now = format_utc_time(now_utc_s());
  for (const std::string* csv :
       {options.data.empty() ? nullptr : &options.data,
        options.data.empty() && options.append ? &*options.append : nullptr}) {
    if (csv == nullptr) continue;
    const BenchImport import = import_bench_csv(*store, *csv, options.sensor, now);
    out << fmt::format("imported {} bench session{} ({} new, {} rows) from {} into {}\n",
                       import.sessions, import.sessions == 1 ? "" : "s", import.new_sessions,
                       import.rows, *csv, store->name());
  }
  const std::vector<host::RecordingRow> rows = stored_bench_rows(*store, session_ids);
  return host::calibrate_rows(store->name(), rows, options.regression);
}

}  // namespace

CLI::App* add_calibrate_command(CLI::App& app, CalibrateOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "Fit clearance = f(voltage, temperature) from a calibration database");
  cmd->add_option("--data", options.data,
                  "calibration database CSV (t_s,clearance_mm,temp_c,voltage_v[,run]); with "
                  "--store, imported into it");
  cmd->add_option("--append", options.append,
                  "a new session (same format) to add to the database (or the store) before "
                  "refitting");
  cmd->add_option("--store", options.store,
                  "sqlite:PATH or postgresql://...: keep the bench sessions there and refit from "
                  "all of them; every refit is kept (docs/store.md)");
  cmd->add_option("--sensor", options.sensor,
                  "with --store: the serial of the sensor the sessions calibrate");
  cmd->add_option("--out", options.out, "where to write the calibration (model.json)")->required();
  cmd->add_option("--max-order", options.regression.max_order, "highest order tried (1 to 6)")
      ->default_val(4)
      ->check(CLI::Range(host::kMinRegressionOrder, host::kMaxRegressionOrder));
  cmd->add_option("--folds", options.regression.folds, "cross-validation folds (2 to 20)")
      ->default_val(5)
      ->check(CLI::Range(2, 20));
  cmd->add_option("--min-r", options.regression.min_r,
                  "correlation the thesis's rule requires (0 < r < 1)")
      ->default_val(0.975)
      ->check(CLI::Range(1e-6, 0.999999));
  return cmd;
}

int run_calibrate_command(const CalibrateOptions& options,
                          const std::vector<std::string>& command_line, std::ostream& out) {
  // A model that cannot be written is found out before the database grows or the fit runs.
  const std::filesystem::path out_path(options.out);
  const std::filesystem::path folder =
      out_path.has_parent_path() ? out_path.parent_path() : std::filesystem::path(".");
  const bool writable =
      std::filesystem::is_directory(folder) && ::access(folder.c_str(), W_OK) == 0 &&
      (!std::filesystem::exists(out_path) ||
       (!std::filesystem::is_directory(out_path) && ::access(out_path.c_str(), W_OK) == 0));
  if (!writable) {
    throw std::runtime_error("--out " + options.out +
                             ": cannot write (the folder must exist and be writable)");
  }
  if (options.data.empty() && !options.store) {
    throw InputError("--data DB.csv or --store URL is required");
  }
  if (options.append && !options.data.empty()) {
    const std::size_t added = host::append_to_database(options.data, *options.append);
    out << fmt::format("appended {} rows from {} to {}\n", added, *options.append, options.data);
  }
  std::unique_ptr<host::Store> store;
  std::vector<std::int64_t> session_ids;
  const Calibration calibration = options.store
                                      ? calibrate_from_store(options, store, session_ids, out)
                                      : calibrate_database(options.data, options.regression);
  print_calibration(calibration, out);
  const auto json = calibration_json(calibration, runtime::generated_by(command_line));
  std::ofstream file(options.out, std::ios::binary);
  file << json.dump(1) << "\n";
  file.close();
  if (!file) throw std::runtime_error("--out " + options.out + ": cannot write");
  out << "  wrote " << options.out << "\n";
  if (store) {
    const std::int64_t id =
        store->record_calibration({format_utc_time(now_utc_s()), options.sensor, json.dump(1),
                                   calibration.rows - calibration.rows_without_reference,
                                   calibration.fit.stats.rmse_mm, session_ids});
    out << fmt::format("  kept in {} as calibration {}\n", store->name(), id);
  }
  return kExitOk;
}

}  // namespace flange::cli
