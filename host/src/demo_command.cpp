// SPDX-License-Identifier: MIT
#include "demo_command.h"

#include <fmt/format.h>

#include <ostream>
#include <sstream>

#include "alias_analysis.h"
#include "cli.h"
#include "input_error.h"
#include "loco_scenario.h"
#include "thesis_filters.h"
#include "thesis_pipeline.h"

namespace flange::host {

namespace {

// Runs one flange command, echoing it; returns its exit status, its output in `captured`.
int step(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
         std::string* captured = nullptr, bool show_output = true) {
  out << "$ flange";
  for (const std::string& arg : args) out << " " << arg;
  out << "\n";
  std::ostringstream command_out;
  std::ostringstream command_err;
  const int status = run_flange(args, command_out, command_err);
  if (show_output) out << command_out.str();
  if (captured != nullptr) *captured = command_out.str();
  err << command_err.str();
  return status;
}

// The line of `text` that contains `key`, trimmed; empty when there is none.
std::string line_with(const std::string& text, const std::string& key) {
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find(key) != std::string::npos) return line.substr(line.find_first_not_of(' '));
  }
  return "";
}

double number_after(const std::string& text, const std::string& key) {
  const std::size_t at = text.find(key);
  if (at == std::string::npos) return 0.0;
  return std::stod(text.substr(at + key.size()));
}

}  // namespace

CLI::App* add_demo_command(CLI::App& app, DemoOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "demo",
      "The whole chain on simulated data: filters, calibration, the Verilated RTL, alarms, the "
      "thesis's chain for comparison, and what 6 Hz sampling does to the wheelset's vibration");
  cmd->add_option("--out", options.out_dir, "folder for everything the demo writes")
      ->default_str("demo_out");
  return cmd;
}

int run_demo_command(const DemoOptions& options, std::ostream& out, std::ostream& err) {
  const std::filesystem::path dir = options.out_dir;
  std::filesystem::create_directories(dir);
  auto path = [&dir](const std::string& name) { return (dir / name).string(); };
  int failures = 0;
  auto must = [&failures, &err](int status, const std::string& what) {
    if (status != 0) {
      err << "flange demo: " << what << " failed (exit status " << status << ")\n";
      ++failures;
    }
    return status == 0;
  };

  out << "== 1. The thesis's filters, quantised for the FPGA (docs/thesis_filters.md)\n";
  for (const coeffs::ThesisFilter& filter : coeffs::thesis_filters()) {
    std::vector<std::string> args = filter.design;
    args.insert(args.end(), {"--out", path(filter.set_name)});
    std::string report;
    std::ostringstream quiet;
    const int status = step(args, out, quiet, &report, false);
    out << "  " << line_with(report, "structure:") << "\n  " << line_with(report, "poles:")
        << "\n  " << line_with(report, "verdict:") << "\n";
    if (filter.expect_rejected) {
      if (status != 3) must(1, "refusing the thesis's 7th-order direct form");
    } else {
      must(status, "designing " + filter.set_name);
    }
  }
  const std::string measurement = path("measurement_sos/filter.json");

  out << "\n== 2. Two simulated bench sessions (the thesis's heated micrometer protocol): one to "
         "calibrate, one to evaluate\n";
  if (!must(step({"simulate", "--scenario", "bench", "--seed", "1", "--out",
                  path("bench_calibration.csv")},
                 out, err),
            "simulating the calibration session") ||
      !must(step({"simulate", "--scenario", "bench", "--seed", "2", "--out",
                  path("bench_evaluation.csv")},
                 out, err),
            "simulating the evaluation session")) {
    return kExitFailure;
  }

  out << "\n== 3. Calibration: the temperature-compensating regression\n";
  if (!must(
          step({"calibrate", "--data", path("bench_calibration.csv"), "--out", path("model.json")},
               out, err),
          "calibrating")) {
    return kExitFailure;
  }

  out << "\n== 4. The evaluation session through the chain, with the Verilated RTL as the "
         "filter (the model checks every output)\n";
  std::string run_text;
  if (!must(step({"run", "--input", path("bench_evaluation.csv"), "--calibration",
                  path("model.json"), "--coeffs", measurement, "--engine", "rtl", "--out",
                  path("bench_results.csv"), "--report", path("bench_report")},
                 out, err, &run_text),
            "running the bench session")) {
    return kExitFailure;
  }

  out << "\n== 5. The same data through the thesis's chain: eq. 3.14 fixed, eq. 4.15 as printed, "
         "double precision\n";
  try {
    const std::uint64_t settle = static_cast<std::uint64_t>(number_after(run_text, "first "));
    const ThesisPipelineResult thesis = run_thesis_pipeline(path("bench_evaluation.csv"), settle);
    const double ours_before = number_after(run_text, "error before filtering: MAE ");
    const double ours_after = number_after(run_text, "error after filtering:  MAE ");
    out << fmt::format("  {:<44} {:>12} {:>12}\n", "", "MAE before", "MAE after");
    out << fmt::format("  {:<44} {:>9.4f} mm {:>9.4f} mm\n",
                       "this project (calibrated fit, RTL filter)", ours_before, ours_after);
    out << fmt::format("  {:<44} {:>9.4f} mm {:>9.4f} mm\n",
                       "thesis (eq. 3.14, eq. 4.15 in floating point)", thesis.before.mae(),
                       thesis.after.mae());
    out << fmt::format("  ratio thesis / this project after filtering: {:.2f}\n",
                       thesis.after.mae() / ours_after);
    out << fmt::format(
        "  (eq. 4.15 as printed has a DC gain of {:.4f}, not 1: {:+.3f} mm of bias at 6 mm)\n",
        thesis.dc_gain, (thesis.dc_gain - 1.0) * 6.0);
  } catch (const InputError& error) {
    must(1, std::string("the thesis chain: ") + error.what());
  }

  out << "\n== 6. A locomotive run: the wheelset's lateral mode against 6 Hz sampling\n";
  if (!must(step({"simulate", "--scenario", "loco", "--fs", "6", "--seed", "3", "--out",
                  path("loco_6hz.csv")},
                 out, err),
            "simulating the loco run at 6 Hz") ||
      !must(step({"simulate", "--scenario", "loco", "--fs", "96", "--seed", "3", "--out",
                  path("loco_96hz.csv")},
                 out, err),
            "simulating the loco run at 96 Hz") ||
      !must(step({"design", "--fs", "96", "--order", "5", "--fc", "0.5742", "--name",
                  "measurement_96hz", "--out", path("measurement_96hz")},
                 out, err),
            "designing the 96 Hz filter") ||
      !must(step({"run", "--input", path("loco_6hz.csv"), "--calibration", path("model.json"),
                  "--coeffs", measurement, "--engine", "rtl", "--out", path("loco_6hz_results.csv"),
                  "--report", path("loco_report")},
                 out, err),
            "running the loco run at 6 Hz") ||
      !must(step({"run", "--input", path("loco_96hz.csv"), "--calibration", path("model.json"),
                  "--coeffs", path("measurement_96hz/filter.json"), "--engine", "rtl", "--out",
                  path("loco_96hz_results.csv")},
                 out, err),
            "running the loco run at 96 Hz")) {
    return kExitFailure;
  }
  try {
    AliasAnalysisInput input;
    input.fast_recording = path("loco_96hz.csv");
    input.slow_output = path("loco_6hz_results.csv");
    input.fast_output = path("loco_96hz_results.csv");
    input.slow_coeffs = measurement;
    input.fast_coeffs = path("measurement_96hz/filter.json");
    const AliasAnalysis alias = analyse_aliasing(input);
    // The model's undamped mode and the truth's spectral peak differ a little: the peak is the
    // damped wheelset's response to the irregularity, read on bins of 96/1024 Hz.
    out << fmt::format(
        "  lateral mode of the wheelset: {:.2f} Hz (peak of the 96 Hz truth's spectrum; the "
        "model's undamped mode is {:.2f} Hz)\n",
        alias.mode_hz, sim::lateral_natural_frequency_hz(sim::LocoRun{}.wheelset));
    out << fmt::format(
        "  sampled at 6 Hz it aliases to {:.2f} Hz, where the measurement filter passes it "
        "({:+.1f} dB):\n    filtered clearance vs the truth below 1 Hz: RMS {:.4f} mm\n",
        alias.alias_hz, alias.slow_gain_at_alias_db, alias.slow_rms_mm);
    out << fmt::format(
        "  sampled at 96 Hz, filtered on the FPGA ({:+.1f} dB at {:.2f} Hz), decimated by 16 "
        "to 6 Hz:\n    filtered clearance vs the truth below 1 Hz: RMS {:.4f} mm ({:.1f} times "
        "smaller)\n",
        alias.fast_gain_at_mode_db, alias.mode_hz, alias.fast_rms_mm,
        alias.slow_rms_mm / alias.fast_rms_mm);
  } catch (const std::exception& error) {
    must(1, std::string("the aliasing analysis: ") + error.what());
  }

  out << "\n== 7. The sim-to-real gap: two bench sessions with an effect the twin was not told "
         "about (the sensor's offset drifts with temperature), diagnosed blind\n";
  const std::string drift = "temp_offset_drift:offset_v_per_c=-0.002";
  if (must(step({"simulate", "--scenario", "bench", "--effect", drift, "--seed", "3", "--out",
                 path("bench_drift_a.csv")},
                out, err),
           "simulating the drifting bench session A") &&
      must(step({"simulate", "--scenario", "bench", "--effect", drift, "--seed", "4", "--out",
                 path("bench_drift_b.csv")},
                out, err),
           "simulating the drifting bench session B")) {
    must(step({"diagnose", "--real", path("bench_drift_a.csv"), "--holdout",
               path("bench_drift_b.csv"), "--out", path("diagnosis")},
              out, err),
         "diagnosing the drifting bench session");
  }

  out << "\n== 8. The gap one layer down: the float design against the Verilated RTL\n";
  must(step({"diagnose", "--hw", "--coeffs", measurement, "--stimulus", "sweep", "--out",
             path("hw_diagnosis")},
            out, err),
       "diagnosing the measurement filter's float-to-RTL gap");
  must(step({"diagnose", "--hw", "--coeffs", path("vehicle_sos/filter.json"), "--thesis-eq-4-20",
             "--stimulus", "step"},
            out, err),
       "diagnosing the thesis's printed eq. 4.20");

  if (failures > 0) {
    err << "flange demo: " << failures << " step(s) failed\n";
    return kExitFailure;
  }
  out << "\ndemo: everything is in " << dir.string() << "/ (reports: bench_report/index.html, "
      << "loco_report/index.html, diagnosis/report.html, hw_diagnosis/hw_diagnosis.html)\n";
  return kExitOk;
}

}  // namespace flange::host
