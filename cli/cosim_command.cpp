// SPDX-License-Identifier: MIT
#include "cosim_command.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.h"
#include "filter_json.h"
#include "verilated_runner.h"

extern char** environ;

namespace flange::cli {
namespace fs = std::filesystem;

CLI::App* add_cosim_command(CLI::App& app, CosimCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "cosim", "Co-simulate the Verilated core against the bit-accurate model, cycle by cycle");
  tb::CosimOptions& r = options.run;
  cmd->add_option("--coeffs", r.coeffs,
                  "filter.json of a coefficient set (iir_coeffs_pkg.sv and coeffs.mem beside it)")
      ->required();
  cmd->add_option("--samples", r.samples, "number of samples (>= 1)")->default_val(10000);
  cmd->add_option("--seed", r.seed, "seed of the random stimuli")->default_val(1);
  cmd->add_option("--stimulus", r.stimulus,
                  "random (uniform, half scale), fullscale (uniform, full range), sweep (log sine "
                  "sweep fc/20 .. 0.49 fs), step (half scale), impulse, or FILE.csv (one integer "
                  "sample per line)")
      ->default_val("random");
  cmd->add_option("--trace", r.trace, "write an FST waveform of the run to this file");
  return cmd;
}

int run_cosim_command(const CosimCommandOptions& options, std::ostream& out, std::ostream& err) {
  const tb::CosimOptions& run = options.run;
  // Bad input fails here, before anything is built: model::FilterJsonError for the set's
  // filter.json, std::invalid_argument for the stimulus and the files beside it (status 2).
  const fs::path set_dir = fs::absolute(run.coeffs).parent_path();
  const fs::path package = set_dir / "iir_coeffs_pkg.sv";
  const fs::path rom = set_dir / "coeffs.mem";
  const model::CoreConfig config = model::load_core_config(run.coeffs);
  const model::FloatDesign design = model::load_float_design(run.coeffs);
  tb::cosim_samples(run, config, design);
  for (const fs::path& f : {package, rom}) {
    if (!fs::is_regular_file(f)) {
      throw std::invalid_argument(fmt::format("{}: missing (it must sit beside {})", f.string(),
                                              run.coeffs.filename().string()));
    }
  }

  // A runner that cannot be built is a failure (std::runtime_error, status 1).
  const fs::path runner = tb::ensure_verilated_runner(run.coeffs, err);
  const fs::path dir = runner.parent_path().parent_path();
  std::vector<std::string> args = {runner.string(),
                                   "--coeffs",
                                   fs::absolute(run.coeffs).string(),
                                   "--samples",
                                   std::to_string(run.samples),
                                   "--seed",
                                   std::to_string(run.seed),
                                   "--stimulus",
                                   run.stimulus};
  if (run.trace) {
    if (run.trace->has_parent_path()) fs::create_directories(run.trace->parent_path());
    args.insert(args.end(), {"--trace", fs::absolute(*run.trace).string()});
  }
  const fs::path run_out = dir / fmt::format("run.{}.out", getpid());
  const fs::path run_err = dir / fmt::format("run.{}.err", getpid());
  const int status = tb::spawn_with_files(args, run_out, run_err);
  err << tb::read_whole_file(run_err);
  out << tb::read_whole_file(run_out);
  fs::remove(run_out);
  fs::remove(run_err);
  if (status == 127) throw std::runtime_error("cannot start " + runner.string());
  return status;
}

}  // namespace flange::cli
