// SPDX-License-Identifier: MIT
#include "synth_command.h"

#include <filesystem>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "cli.h"
#include "data_dir.h"
#include "yosys_synthesis.h"

namespace flange::cli {
namespace fs = std::filesystem;

CLI::App* add_synth_command(CLI::App& app, SynthOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "synth", "Yosys synthesis for the XC7A35T: core and Basys-3 top, utilisation and depth");
  cmd->add_option("--coeffs", options.coeffs,
                  "coefficient set folder (iir_coeffs_pkg.sv, coeffs.mem); a relative one is "
                  "looked up in the working folder, then in the data folder (flange --version)")
      ->default_val(options.coeffs);
  cmd->add_option("--out", options.out, "Markdown report to write")->default_val(options.out);
  cmd->add_option("--yosys", options.yosys, "Yosys executable")->default_val(options.yosys);
  cmd->add_option("--max-core-lut-percent", options.max_core_lut_percent,
                  "fail when the core uses more of the device's LUTs (0-100)")
      ->default_val(options.max_core_lut_percent)
      ->check(CLI::Range(0.0, 100.0));
  return cmd;
}

int run_synth_command(const SynthOptions& options, std::ostream& out, std::ostream& err) {
  tb::SynthesisRequest request;
  request.yosys = options.yosys;
  tb::SynthesisResult result;
  try {
    request.data_dir = runtime::data_dir().root;
    request.coeff_set = tb::find_coeff_set(request.data_dir, options.coeffs);
    result = tb::synthesise(request);
  } catch (const runtime::DataDirNotFound& missing) {
    err << "flange synth: " << missing.what() << "\n";
    return kExitFailure;
  } catch (const std::invalid_argument& missing) {
    err << "flange synth: " << missing.what() << "\n";
    return kExitBadArgument;
  } catch (const tb::SynthesisFailed& failed) {
    err << "flange synth: " << failed.what() << "\n";
    return kExitFailure;
  }
  const std::string failures = tb::check_utilisation(
      result.core.utilisation, result.top.utilisation, options.max_core_lut_percent);
  const fs::path out_path(options.out);
  if (out_path.has_parent_path()) fs::create_directories(out_path.parent_path());
  std::ofstream file(out_path);
  if (!file) {
    err << "flange synth: cannot write " << options.out << "\n";
    return kExitFailure;
  }
  file << tb::synthesis_report_markdown(result, options.max_core_lut_percent, failures);
  out << "synth: " << tb::synthesis_summary_line(result) << "; report " << options.out << "\n";
  if (!failures.empty()) {
    err << "flange synth: " << failures << "(reproduce: flange synth --coeffs " << options.coeffs
        << ")\n";
    return kExitFailure;
  }
  return kExitOk;
}

}  // namespace flange::cli
