// SPDX-License-Identifier: MIT
#include "run_command.h"

#include <ostream>

#include "cli.h"
#include "input_error.h"
#include "run_report.h"

namespace flange::cli {

CLI::App* add_run_command(CLI::App& app, host::RunOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "run", "Run a recording through regression, the IIR filter and the wear thresholds");
  cmd->add_option("--input", options.input, "recording CSV (t_s,clearance_mm,temp_c,voltage_v)")
      ->required();
  cmd->add_option("--calibration", options.calibration, "model.json from flange calibrate")
      ->required();
  cmd->add_option("--coeffs", options.coeffs, "filter.json from flange design")->required();
  cmd->add_option("--engine", options.engine,
                  "model: bit-accurate model; rtl: Verilated RTL checked by the model; float: "
                  "double-precision design")
      ->check(CLI::IsMember({"model", "rtl", "float"}))
      ->default_str("model");
  cmd->add_option("--out", options.out_csv,
                  "output CSV: t_s,clearance_raw_mm,clearance_filt_mm,flange_mm,alarm,flags");
  cmd->add_option("--report", options.report_dir, "folder for the HTML report");
  cmd->add_flag("--lenient", options.lenient,
                "flag bad rows (the filter holds its last input) instead of stopping");
  host::ThresholdConfig& t = options.thresholds;
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

int run_run_command(const host::RunOptions& options, std::ostream& out, std::ostream& err) {
  try {
    host::RunTrace trace;
    const host::RunSummary summary =
        host::run_pipeline(options, options.report_dir ? &trace : nullptr);
    out << run_summary_text(options, summary);
    if (options.out_csv) out << "  wrote " << *options.out_csv << "\n";
    if (options.report_dir) {
      write_run_report(*options.report_dir, options, summary, trace);
      out << "  report " << *options.report_dir << "/index.html\n";
    }
    return summary.rtl_mismatches > 0 ? kExitFailure : kExitOk;
  } catch (const host::InputError& error) {
    err << "flange run: " << error.what() << "\n";
    return kExitBadArgument;
  }
}

}  // namespace flange::cli
