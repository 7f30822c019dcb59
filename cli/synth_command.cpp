// SPDX-License-Identifier: MIT
#include "synth_command.h"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <ostream>
#include <stdexcept>

#include "cli.h"
#include "data_dir.h"
#include "yosys_synthesis.h"

namespace flange::cli {
namespace fs = std::filesystem;

namespace {

// The command line that remakes the report, as the report names it.
std::string command_line(const SynthOptions& options) {
  std::string command = "flange synth";
  for (const std::string& set : options.coeffs) command += " --coeffs " + set;
  const SynthOptions defaults;
  if (options.max_core_lut_percent != defaults.max_core_lut_percent)
    command += fmt::format(" --max-core-lut-percent {:g}", options.max_core_lut_percent);
  if (options.min_slack_percent != defaults.min_slack_percent)
    command += fmt::format(" --min-slack-percent {:g}", options.min_slack_percent);
  command += " --out " + options.out;
  if (!options.json.empty()) command += " --json " + options.json;
  if (!options.vivado_report.empty()) command += " --vivado-report " + options.vivado_report;
  return command;
}

bool write_file(const fs::path& path, const std::string& text) {
  if (path.has_parent_path()) fs::create_directories(path.parent_path());
  std::ofstream file(path);
  return static_cast<bool>(file << text);
}

}  // namespace

CLI::App* add_synth_command(CLI::App& app, SynthOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "synth",
      "Yosys synthesis for the XC7A35T: core and Basys-3 top, utilisation, depth and a pre-route "
      "timing estimate at 100 MHz");
  cmd->add_option("--coeffs", options.coeffs,
                  "coefficient set folders (iir_coeffs_pkg.sv, coeffs.mem), one or more; a "
                  "relative one is looked up in the working folder, then in the data folder "
                  "(flange --version)")
      ->default_val(options.coeffs);
  cmd->add_option("--out", options.out, "Markdown report to write")->default_val(options.out);
  cmd->add_option("--json", options.json,
                  "JSON report to write (default: beside --out, with the extension .json)");
  cmd->add_option("--yosys", options.yosys, "Yosys executable")->default_val(options.yosys);
  cmd->add_option("--vivado-report", options.vivado_report,
                  "folder of rtl/board/vivado_build.tcl's timing_summary.rpt and utilization.rpt: "
                  "Vivado's routed figures beside the estimate (of the first set's board top)");
  cmd->add_option("--max-core-lut-percent", options.max_core_lut_percent,
                  "fail when the core uses more of the device's LUTs (0-100)")
      ->default_val(options.max_core_lut_percent)
      ->check(CLI::Range(0.0, 100.0));
  cmd->add_option("--min-slack-percent", options.min_slack_percent,
                  "fail when a top's estimated slack is a smaller share of the period (-100 to "
                  "100; below 0: a bound on how far a top known to miss may fall)")
      ->default_val(options.min_slack_percent)
      ->check(CLI::Range(-100.0, 100.0));
  return cmd;
}

int run_synth_command(const SynthOptions& options, std::ostream& out, std::ostream& err) {
  tb::ReportSettings settings;
  settings.command = command_line(options);
  settings.max_core_lut_percent = options.max_core_lut_percent;
  settings.min_slack_percent = options.min_slack_percent;
  // The Vivado reports first: a bad one (tb::VivadoReportError, status 2) fails in a second, not
  // after minutes of Yosys. A missing report, data folder or a failed Yosys run is status 1, a
  // missing coefficient set (std::invalid_argument) 2.
  if (!options.vivado_report.empty()) {
    settings.vivado = tb::read_vivado_report(options.vivado_report);
  }
  tb::SynthesisRequest request;
  request.yosys = options.yosys;
  request.data_dir = runtime::data_dir().root;
  std::vector<fs::path> sets;
  for (const std::string& set : options.coeffs) {
    sets.push_back(tb::find_coeff_set(request.data_dir, set));
  }
  std::vector<tb::SynthesisResult> results;
  for (const fs::path& set : sets) {
    request.coeff_set = set;
    results.push_back(tb::synthesise(request));
    settings.allowance = request.allowance;
    out << "synth: " << tb::synthesis_summary_line(results.back()) << "\n";
  }
  for (const tb::SynthesisResult& r : results) {
    settings.failures +=
        tb::check_utilisation(r.core.utilisation, r.top.utilisation, options.max_core_lut_percent);
    settings.failures += tb::check_timing(r, options.min_slack_percent);
  }
  const fs::path json_path = options.json.empty() ? fs::path(options.out).replace_extension(".json")
                                                  : fs::path(options.json);
  if (!write_file(options.out, tb::synthesis_report_markdown(results, settings))) {
    throw std::runtime_error("cannot write " + options.out);
  }
  if (!write_file(json_path, tb::synthesis_report_json(results, settings))) {
    throw std::runtime_error("cannot write " + json_path.string());
  }
  out << "synth: report " << options.out << ", " << json_path.string() << "\n";
  if (!settings.failures.empty()) {
    err << "flange synth: " << settings.failures << "(reproduce: " << settings.command << ")\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace flange::cli
