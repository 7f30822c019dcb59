// SPDX-License-Identifier: MIT
#include "cli.h"

#include <CLI/CLI.hpp>
#include <exception>
#include <optional>
#include <ostream>

#include "calibrate_command.h"
#include "cosim_command.h"
#include "demo_command.h"
#include "design_command.h"
#include "diagnose_command.h"
#include "diagnose_selftest_command.h"
#include "exit_status.h"
#include "hw_diagnose_command.h"
#include "input_notes.h"
#include "maintenance_command.h"
#include "parallel_work.h"
#include "printable_stream.h"
#include "run_command.h"
#include "simulate_command.h"
#include "stream_command.h"
#include "synth_command.h"
#include "wear_command.h"

namespace flange::cli {

namespace {

// CLI11 says "Could not convert: --order = 1.5" for a value of the wrong type; say what the option
// takes too (its help text carries the valid range).
std::string explain_parse_error(const CLI::App& app, const CLI::ParseError& error) {
  const std::string what = error.what();
  const std::string prefix = "Could not convert: ";
  const std::size_t equals = what.find(" = ");
  if (what.rfind(prefix, 0) != 0 || equals == std::string::npos) return what;
  const std::string name = what.substr(prefix.size(), equals - prefix.size());
  const std::string value = what.substr(equals + 3);
  const CLI::Option* option = app.get_option_no_throw(name);
  if (option == nullptr) return what;
  return name + ": '" + value + "' is not a valid value; expected " + option->get_description();
}

// Every subcommand's options, filled by the parse.
struct Subcommands {
  DesignOptions design_options;
  CalibrateOptions calibrate_options;
  RunCommandOptions run_options;
  DemoOptions demo_options;
  SimulateOptions simulate_options;
  CosimCommandOptions cosim_options;
  SynthOptions synth_options;
  StreamOptions stream_options;
  DiagnoseCommandOptions diagnose_options;
  HwDiagnoseOptions hw_diagnose_options;    // --hw: the float design against the Verilated RTL
  SelftestCommandOptions selftest_options;  // --selftest: the blind check of the data layer
  WearOptions wear_options;
  MaintenanceOptions maintenance_options;
  CLI::App* design = nullptr;
  CLI::App* calibrate = nullptr;
  CLI::App* run = nullptr;
  CLI::App* demo = nullptr;
  CLI::App* simulate = nullptr;
  CLI::App* cosim = nullptr;
  CLI::App* synth = nullptr;
  CLI::App* stream = nullptr;
  CLI::App* diagnose = nullptr;
  CLI::App* wear = nullptr;
  CLI::App* maintenance = nullptr;

  void add_to(CLI::App& app) {
    design = add_design_command(app, design_options);
    calibrate = add_calibrate_command(app, calibrate_options);
    run = add_run_command(app, run_options);
    demo = add_demo_command(app, demo_options);
    simulate = add_simulate_command(app, simulate_options);
    cosim = add_cosim_command(app, cosim_options);
    synth = add_synth_command(app, synth_options);
    stream = add_stream_command(app, stream_options);
    diagnose = add_diagnose_command(app, diagnose_options);
    wear = add_wear_command(app, wear_options);
    maintenance = add_maintenance_command(app, maintenance_options);
    add_hw_diagnose_options(*diagnose, hw_diagnose_options);
    add_selftest_options(*diagnose, selftest_options);
    // The three layers of diagnose take different inputs: say so rather than ignore one.
    for (const char* data_option : {"--real", "--holdout", "--holdout-fraction", "--real-start",
                                    "--holdout-start", "--twin"}) {
      diagnose->get_option("--selftest")->excludes(data_option);
      diagnose->get_option("--hw")->excludes(data_option);
    }
    diagnose->get_option("--hw")->excludes("--selftest");
  }

  // Runs the parsed subcommand; its exit status. It reports a failure by throwing, and
  // report_exit (exit_status.h) turns what it throws into the status and the line on `err`.
  int run_parsed(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
    if (design->parsed()) return run_design_command(design_options, args, out);
    if (calibrate->parsed()) return run_calibrate_command(calibrate_options, args, out);
    if (run->parsed()) return run_run_command(run_options, args, out);
    if (demo->parsed()) return run_demo_command(demo_options, out, err);
    if (simulate->parsed()) return run_simulate_command(simulate_options, args, out);
    if (cosim->parsed()) return run_cosim_command(cosim_options, out, err);
    if (synth->parsed()) return run_synth_command(synth_options, out, err);
    if (stream->parsed()) return run_stream_command(stream_options, out, err);
    if (diagnose->parsed()) return run_diagnose_layer(out, err);
    if (wear->parsed()) return run_wear_command(wear_options, args, out, err);
    if (maintenance->parsed()) return run_maintenance_command(maintenance_options, out);
    return kExitBadArgument;
  }

  // The name the parsed subcommand's errors start with: "flange design", and for the layers of
  // diagnose "flange diagnose --hw", "flange diagnose --selftest [--reality alt|third]".
  std::string command_name(const CLI::App& app) const {
    std::string name = "flange";
    for (const CLI::App* sub : app.get_subcommands()) name += " " + sub->get_name();
    if (diagnose->parsed() && hw_diagnose_options.hw) return name + " --hw";
    if (diagnose->parsed() && selftest_options.selftest) {
      const std::string& reality = selftest_options.reality;
      return name + " --selftest" + (reality == "twin" ? "" : " --reality " + reality);
    }
    return name;
  }

  // --hw, --selftest or the data layer.
  int run_diagnose_layer(std::ostream& out, std::ostream& err) {
    if (hw_diagnose_options.hw) {
      // --seed and --out are the data layer's options; the hardware layer reads them too.
      hw_diagnose_options.request.seed = diagnose_options.seed;
      if (!diagnose_options.out.empty()) hw_diagnose_options.out = diagnose_options.out;
      return run_hw_diagnosis(hw_diagnose_options, out, err);
    }
    // --jobs: the threads of the whole run, a diagnosis's or a self-test's (parallel_work.h).
    if (selftest_options.run.jobs > 0) diagnose::set_worker_threads(selftest_options.run.jobs);
    if (selftest_options.selftest) {
      // --seed, --out and --bootstrap are the data layer's options; the self-test reads them.
      selftest_options.run.seed = diagnose_options.seed;
      selftest_options.run.bootstrap_rounds = diagnose_options.bootstrap_rounds;
      if (!diagnose_options.out.empty()) selftest_options.out = diagnose_options.out;
      return run_selftest_command(selftest_options, out);
    }
    return run_diagnose_command(diagnose_options, out);
  }
};

// Parses `args`: a status to return at once (help, or a parse error named on `err`), or nothing.
std::optional<int> parse_command_line(CLI::App& app, const std::vector<std::string>& args,
                                      std::ostream& out, std::ostream& err) {
  std::vector<const char*> argv{"flange"};
  for (const std::string& arg : args) argv.push_back(arg.c_str());
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::Success& help_or_version) {  // --help, --help-all, --version: status 0
    return app.exit(help_or_version, out, err);
  } catch (const CLI::ParseError& error) {
    std::string where = "flange";
    const CLI::App* parsed = &app;
    for (const CLI::App* sub : app.get_subcommands()) {
      where += " " + sub->get_name();
      parsed = sub;
    }
    err << where << ": " << explain_parse_error(*parsed, error) << "\n";
    return kExitBadArgument;
  }
  return std::nullopt;
}

}  // namespace

int run_flange(const std::vector<std::string>& args, std::ostream& out, std::ostream& raw_err,
               std::string_view commit) {
  PrintableStream err(raw_err);
  const host::ScopedInputNotes notes(err);
  CLI::App app{"flange: FPGA IIR filter for wheel-flange wear measurement"};
  app.name("flange");
  app.require_subcommand(1);
  app.fallthrough(false);
  app.set_version_flag(
      "--version", [commit] { return version_text(commit); },
      "print the version, the git commit, the data folder and the Verilator and Yosys found");
  Subcommands subcommands;
  subcommands.add_to(app);
  if (const std::optional<int> status = parse_command_line(app, args, out, err)) return *status;
  try {
    return subcommands.run_parsed(args, out, err);
  } catch (const std::exception& error) {  // the one handler: exit_status.h's table
    return report_exit(subcommands.command_name(app), error, err);
  }
}

}  // namespace flange::cli
