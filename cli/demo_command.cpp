// SPDX-License-Identifier: MIT
#include "demo_command.h"

#include <fmt/format.h>

#include <filesystem>
#include <ostream>
#include <sstream>

#include "alias_analysis.h"
#include "cli.h"
#include "input_error.h"
#include "loco_scenario.h"
#include "thesis_filters.h"
#include "thesis_pipeline.h"

namespace flange::cli {

using host::AliasAnalysis;
using host::AliasAnalysisInput;
using host::InputError;
using host::ThesisPipelineResult;

namespace {

// The demo's folder, its streams and its count of failed steps.
struct Demo {
  std::filesystem::path dir;
  std::ostream& out;
  std::ostream& err;
  int failures = 0;

  std::string path(const std::string& name) const { return (dir / name).string(); }

  // Counts a failed step (non-zero status) with one line naming it; true when it succeeded.
  bool must(int status, const std::string& what) {
    if (status != 0) {
      err << "flange demo: " << what << " failed (exit status " << status << ")\n";
      ++failures;
    }
    return status == 0;
  }

  // Runs one flange command, echoing it; returns its exit status, its output in `captured`.
  int step(const std::vector<std::string>& args, std::string* captured = nullptr,
           bool show_output = true) {
    return step(args, captured, show_output, err);
  }
  int step(const std::vector<std::string>& args, std::string* captured, bool show_output,
           std::ostream& command_errors) {
    out << "$ flange";
    for (const std::string& arg : args) out << " " << arg;
    out << "\n";
    std::ostringstream command_out;
    std::ostringstream command_err;
    const int status = run_flange(args, command_out, command_err);
    if (show_output) out << command_out.str();
    if (captured != nullptr) *captured = command_out.str();
    command_errors << command_err.str();
    return status;
  }
};

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

// 1. The thesis's filters, designed and quantised (the 7th-order direct form must be refused).
void design_thesis_filters(Demo& demo) {
  demo.out << "== 1. The thesis's filters, quantised for the FPGA (docs/thesis_filters.md)\n";
  for (const coeffs::ThesisFilter& filter : coeffs::thesis_filters()) {
    std::vector<std::string> args = filter.design;
    args.insert(args.end(), {"--out", demo.path(filter.set_name)});
    std::string report;
    std::ostringstream quiet;
    const int status = demo.step(args, &report, false, quiet);
    demo.out << "  " << line_with(report, "structure:") << "\n  " << line_with(report, "poles:")
             << "\n  " << line_with(report, "verdict:") << "\n";
    if (filter.expect_rejected) {
      if (status != 3) demo.must(1, "refusing the thesis's 7th-order direct form");
    } else {
      demo.must(status, "designing " + filter.set_name);
    }
  }
}

// 2. Two bench sessions: one to calibrate, one to evaluate.
bool simulate_bench_sessions(Demo& demo) {
  demo.out
      << "\n== 2. Two simulated bench sessions (the thesis's heated micrometer protocol): one to "
         "calibrate, one to evaluate\n";
  if (!demo.must(demo.step({"simulate", "--scenario", "bench", "--seed", "1", "--out",
                            demo.path("bench_calibration.csv")}),
                 "simulating the calibration session") ||
      !demo.must(demo.step({"simulate", "--scenario", "bench", "--seed", "2", "--out",
                            demo.path("bench_evaluation.csv")}),
                 "simulating the evaluation session")) {
    return false;
  }

  return true;
}

// 3. The temperature-compensating regression.
bool calibrate_on_first_session(Demo& demo) {
  demo.out << "\n== 3. Calibration: the temperature-compensating regression\n";
  if (!demo.must(demo.step({"calibrate", "--data", demo.path("bench_calibration.csv"), "--out",
                            demo.path("model.json")}),
                 "calibrating")) {
    return false;
  }

  return true;
}

// 4. The evaluation session through the chain with the Verilated RTL; its summary in run_text.
bool run_evaluation_through_rtl(Demo& demo, const std::string& measurement, std::string& run_text) {
  demo.out << "\n== 4. The evaluation session through the chain, with the Verilated RTL as the "
              "filter (the model checks every output)\n";
  if (!demo.must(
          demo.step({"run", "--input", demo.path("bench_evaluation.csv"), "--calibration",
                     demo.path("model.json"), "--coeffs", measurement, "--engine", "rtl", "--out",
                     demo.path("bench_results.csv"), "--report", demo.path("bench_report")},
                    &run_text),
          "running the bench session")) {
    return false;
  }

  return true;
}

// 5. The thesis's own chain on the same data, beside this project's figures.
void compare_with_thesis_chain(Demo& demo, const std::string& run_text) {
  demo.out
      << "\n== 5. The same data through the thesis's chain: eq. 3.14 fixed, eq. 4.15 as printed, "
         "double precision\n";
  try {
    const std::uint64_t settle = static_cast<std::uint64_t>(number_after(run_text, "first "));
    const ThesisPipelineResult thesis =
        host::run_thesis_pipeline(demo.path("bench_evaluation.csv"), settle);
    const double ours_before = number_after(run_text, "error before filtering: MAE ");
    const double ours_after = number_after(run_text, "error after filtering:  MAE ");
    demo.out << fmt::format("  {:<44} {:>12} {:>12}\n", "", "MAE before", "MAE after");
    demo.out << fmt::format("  {:<44} {:>9.4f} mm {:>9.4f} mm\n",
                            "this project (calibrated fit, RTL filter)", ours_before, ours_after);
    demo.out << fmt::format("  {:<44} {:>9.4f} mm {:>9.4f} mm\n",
                            "thesis (eq. 3.14, eq. 4.15 in floating point)", thesis.before.mae(),
                            thesis.after.mae());
    demo.out << fmt::format("  ratio thesis / this project after filtering: {:.2f}\n",
                            thesis.after.mae() / ours_after);
    demo.out << fmt::format(
        "  (eq. 4.15 as printed has a DC gain of {:.4f}, not 1: {:+.3f} mm of bias at 6 mm)\n",
        thesis.dc_gain, (thesis.dc_gain - 1.0) * 6.0);
  } catch (const InputError& error) {
    // Recovers: a failed step is counted (the demo exits 1 at the end) and the demo goes on.
    demo.must(1, std::string("the thesis chain: ") + error.what());
  }
}

// 6. The locomotive run at 6 Hz and at 96 Hz: where the wheelset's lateral mode lands.
bool show_lateral_mode_aliasing(Demo& demo, const std::string& measurement) {
  demo.out << "\n== 6. A locomotive run: the wheelset's lateral mode against 6 Hz sampling\n";
  if (!demo.must(demo.step({"simulate", "--scenario", "loco", "--fs", "6", "--seed", "3", "--out",
                            demo.path("loco_6hz.csv")}),
                 "simulating the loco run at 6 Hz") ||
      !demo.must(demo.step({"simulate", "--scenario", "loco", "--fs", "96", "--seed", "3", "--out",
                            demo.path("loco_96hz.csv")}),
                 "simulating the loco run at 96 Hz") ||
      !demo.must(demo.step({"design", "--fs", "96", "--order", "5", "--fc", "0.5742", "--name",
                            "measurement_96hz", "--out", demo.path("measurement_96hz")}),
                 "designing the 96 Hz filter") ||
      !demo.must(
          demo.step({"run", "--input", demo.path("loco_6hz.csv"), "--calibration",
                     demo.path("model.json"), "--coeffs", measurement, "--engine", "rtl", "--out",
                     demo.path("loco_6hz_results.csv"), "--report", demo.path("loco_report")}),
          "running the loco run at 6 Hz") ||
      !demo.must(
          demo.step({"run", "--input", demo.path("loco_96hz.csv"), "--calibration",
                     demo.path("model.json"), "--coeffs", demo.path("measurement_96hz/filter.json"),
                     "--engine", "rtl", "--out", demo.path("loco_96hz_results.csv")}),
          "running the loco run at 96 Hz")) {
    return false;
  }
  try {
    AliasAnalysisInput input;
    input.fast_recording = demo.path("loco_96hz.csv");
    input.slow_output = demo.path("loco_6hz_results.csv");
    input.fast_output = demo.path("loco_96hz_results.csv");
    input.slow_coeffs = measurement;
    input.fast_coeffs = demo.path("measurement_96hz/filter.json");
    const AliasAnalysis alias = host::analyse_aliasing(input);
    // The model's undamped mode and the truth's spectral peak differ a little: the peak is the
    // damped wheelset's response to the irregularity, read on bins of 96/1024 Hz.
    demo.out << fmt::format(
        "  lateral mode of the wheelset: {:.2f} Hz (peak of the 96 Hz truth's spectrum; the "
        "model's undamped mode is {:.2f} Hz)\n",
        alias.mode_hz, sim::lateral_natural_frequency_hz(sim::LocoRun{}.wheelset));
    demo.out << fmt::format(
        "  sampled at 6 Hz it aliases to {:.2f} Hz, where the measurement filter passes it "
        "({:+.1f} dB):\n    filtered clearance vs the truth below 1 Hz: RMS {:.4f} mm\n",
        alias.alias_hz, alias.slow_gain_at_alias_db, alias.slow_rms_mm);
    demo.out << fmt::format(
        "  sampled at 96 Hz, filtered on the FPGA ({:+.1f} dB at {:.2f} Hz), decimated by 16 "
        "to 6 Hz:\n    filtered clearance vs the truth below 1 Hz: RMS {:.4f} mm ({:.1f} times "
        "smaller)\n",
        alias.fast_gain_at_mode_db, alias.mode_hz, alias.fast_rms_mm,
        alias.slow_rms_mm / alias.fast_rms_mm);
  } catch (const std::exception& error) {
    // Recovers: a failed step is counted (the demo exits 1 at the end) and the demo goes on.
    demo.must(1, std::string("the aliasing analysis: ") + error.what());
  }

  return true;
}

// 7. A bench session with a withheld sensor effect, diagnosed blind.
void diagnose_withheld_effect(Demo& demo) {
  demo.out
      << "\n== 7. The sim-to-real gap: two bench sessions with an effect the twin was not told "
         "about (the sensor's offset drifts with temperature), diagnosed blind\n";
  const std::string drift = "temp_offset_drift:offset_v_per_c=-0.002";
  if (demo.must(demo.step({"simulate", "--scenario", "bench", "--effect", drift, "--seed", "3",
                           "--out", demo.path("bench_drift_a.csv")}),
                "simulating the drifting bench session A") &&
      demo.must(demo.step({"simulate", "--scenario", "bench", "--effect", drift, "--seed", "4",
                           "--out", demo.path("bench_drift_b.csv")}),
                "simulating the drifting bench session B")) {
    demo.must(demo.step({"diagnose", "--real", demo.path("bench_drift_a.csv"), "--holdout",
                         demo.path("bench_drift_b.csv"), "--out", demo.path("diagnosis")}),
              "diagnosing the drifting bench session");
  }
}

// 8. The float design against the Verilated RTL, and eq. 4.20 as printed.
void diagnose_hardware_gap(Demo& demo, const std::string& measurement) {
  demo.out << "\n== 8. The gap one layer down: the float design against the Verilated RTL\n";
  demo.must(demo.step({"diagnose", "--hw", "--coeffs", measurement, "--stimulus", "sweep", "--out",
                       demo.path("hw_diagnosis")}),
            "diagnosing the measurement filter's float-to-RTL gap");
  demo.must(demo.step({"diagnose", "--hw", "--coeffs", demo.path("vehicle_sos/filter.json"),
                       "--thesis-eq-4-20", "--stimulus", "step"}),
            "diagnosing the thesis's printed eq. 4.20");
}

// 9. A whole locomotive: twelve wheels, each with its own sensor, all on one core (one DSP48E1).
void run_whole_locomotive(Demo& demo) {
  demo.out << "\n== 9. A whole locomotive: twelve wheels, each with its own sensor, all filtered by "
              "one core (one DSP48E1, twelve channels)\n";
  const std::string set = demo.path("locomotive_sos");
  if (!demo.must(demo.step({"design", "--fs", "6", "--order", "5", "--fc", "0.5742", "--structure",
                            "sos", "--channels", "12", "--name", "locomotive", "--no-plot", "--out",
                            set}),
                 "designing the twelve-channel core")) {
    return;
  }
  demo.must(demo.step({"cosim", "--coeffs", set + "/filter.json", "--samples", "12000"}),
            "co-simulating the twelve-channel core");
  // The twelve-channel core and board keep the 20 % of estimated slack every top keeps.
  demo.must(demo.step({"synth", "--coeffs", set, "--out", demo.path("locomotive_synthesis.md"),
                       "--max-core-lut-percent", "5"}),
            "synthesising the twelve-channel core");
  if (demo.must(demo.step({"simulate", "--scenario", "loco", "--wheels", "12", "--fs", "6",
                           "--seed", "3", "--out", demo.path("locomotive")}),
                "simulating the twelve-wheel locomotive")) {
    demo.must(demo.step({"run", "--manifest", demo.path("locomotive/locomotive.json"),
                         "--calibration", demo.path("model.json"), "--coeffs",
                         set + "/filter.json", "--engine", "rtl", "--out",
                         demo.path("locomotive_run")}),
              "running every channel of the locomotive");
    demo.out
        << "  in the curve the wheelset sits 2.56 mm towards the left rail: the right (inner)\n"
           "  sensors read that much more than their wear, so their warnings come and go\n"
           "  with the curve (docs/locomotive.md, \"What the example shows\")\n";
  }
}

// 10. A small fleet over four weeks into an SQLite store, and every wheel's wear from it.
void follow_a_fleet(Demo& demo) {
  demo.out << "\n== 10. A depot's fleet: two locomotives over four weeks into an SQLite store, "
              "then every wheel's wear, its rate and when it reaches the limits "
              "(docs/fleet.md)\n";
  const std::filesystem::path dir = demo.dir / "fleet";
  std::filesystem::remove_all(dir);  // the fleet goes into a new store every time
  std::filesystem::create_directories(dir);
  const std::string store = "sqlite:" + (dir / "fleet.db").string();
  if (demo.must(demo.step({"simulate", "--scenario", "fleet", "--locomotives", "2", "--days", "28",
                           "--seed", "5", "--store", store}),
                "simulating the fleet")) {
    demo.must(demo.step({"wear", "--store", store, "--out", (dir / "wear").string()}),
              "estimating the fleet's wear");
  }
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
  Demo demo{options.out_dir, out, err};
  std::filesystem::create_directories(demo.dir);
  const std::string measurement = demo.path("measurement_sos/filter.json");
  std::string run_text;
  design_thesis_filters(demo);
  if (!simulate_bench_sessions(demo) || !calibrate_on_first_session(demo) ||
      !run_evaluation_through_rtl(demo, measurement, run_text)) {
    return kExitFailure;
  }
  compare_with_thesis_chain(demo, run_text);
  if (!show_lateral_mode_aliasing(demo, measurement)) return kExitFailure;
  diagnose_withheld_effect(demo);
  diagnose_hardware_gap(demo, measurement);
  run_whole_locomotive(demo);
  follow_a_fleet(demo);

  if (demo.failures > 0) {
    err << "flange demo: " << demo.failures << " step(s) failed\n";
    return kExitFailure;
  }
  out << "\ndemo: everything is in " << demo.dir.string() << "/ (reports: bench_report/index.html, "
      << "loco_report/index.html, diagnosis/report.html, hw_diagnosis/hw_diagnosis.html, "
      << "locomotive_run/index.html, fleet/wear/index.html)\n";
  return kExitOk;
}

}  // namespace flange::cli
