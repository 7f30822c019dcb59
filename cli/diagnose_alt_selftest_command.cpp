// SPDX-License-Identifier: MIT
#include "diagnose_alt_selftest_command.h"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <ostream>
#include <stdexcept>

#include "alt_selftest_report.h"
#include "alt_truth.h"
#include "blind_check_files.h"
#include "cli.h"
#include "input_error.h"

namespace flange::cli {
namespace fs = std::filesystem;

namespace {

// selftest.json, selftest.md and, for one pair, its sessions and truth; throws
// std::runtime_error.
void write_alt_files(const SelftestCommandOptions& options, const std::string& header,
                     const std::vector<diagnose::AltPairResult>& results,
                     const diagnose::AltSummary& summary, std::ostream& out) {
  const diagnose::BlindStyle style = diagnose::alt_selftest_style(options.run);
  const std::vector<diagnose::BlindRow> rows =
      diagnose::blind_rows(diagnose::alt_reality_for_check(), results);
  const fs::path dir(*options.out);
  fs::create_directories(dir);
  const diagnose::AltPairResult& first = results.front();
  if (first.sessions) {
    print_same_diagnosis(alt_reality::write_alt_pair(dir, first.spec, *first.sessions),
                         diagnose::alt_session_start_utc_s(first.spec.fit),
                         diagnose::alt_session_start_utc_s(first.spec.heldout),
                         diagnose::blind_diagnose_options(first.spec.index, options.run), out);
  }
  write_blind_check_files(dir, diagnose::blind_json(options.run, style, rows, summary),
                          diagnose::blind_markdown(header, style, rows, summary), out);
}

}  // namespace

int run_alt_selftest_command(const SelftestCommandOptions& options, std::ostream& out) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<diagnose::AltPairResult> results = diagnose::run_alt_selftest(options.run);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const diagnose::AltSummary summary = diagnose::summarise_alt_selftest(results);
  const std::string header = diagnose::alt_selftest_header(summary, options.run);
  out << diagnose::blind_terminal_report(
      header, diagnose::alt_selftest_style(options.run),
      diagnose::blind_rows(diagnose::alt_reality_for_check(), results), summary);
  out << fmt::format("seed {}: aims {} ({:.0f} s)\n", options.run.seed,
                     summary.aims_met() ? "met" : "MISSED", seconds);
  if (options.out) write_alt_files(options, header, results, summary, out);
  return summary.aims_met() ? kExitOk : kExitFailure;
}

}  // namespace flange::cli
