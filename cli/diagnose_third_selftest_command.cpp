// SPDX-License-Identifier: MIT
#include "diagnose_third_selftest_command.h"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <ostream>
#include <stdexcept>

#include "blind_check_files.h"
#include "cli.h"
#include "third_selftest_report.h"
#include "third_truth.h"

namespace flange::cli {
namespace fs = std::filesystem;

namespace {

// selftest.json, selftest.md and, for one pair, its sessions and truth; throws
// std::runtime_error.
void write_third_files(const SelftestCommandOptions& options, const std::string& header,
                       const std::vector<diagnose::ThirdPairResult>& results,
                       const diagnose::BlindSummary& summary, std::ostream& out) {
  const diagnose::BlindStyle style = diagnose::third_selftest_style(options.run);
  const std::vector<diagnose::BlindRow> rows =
      diagnose::blind_rows(diagnose::third_reality_for_check(), results);
  const fs::path dir(*options.out);
  fs::create_directories(dir);
  const diagnose::ThirdPairResult& first = results.front();
  if (first.sessions) {
    print_same_diagnosis(third_reality::write_third_pair(dir, first.spec, *first.sessions),
                         diagnose::third_session_start_utc_s(first.spec.fit),
                         diagnose::third_session_start_utc_s(first.spec.heldout),
                         diagnose::blind_diagnose_options(first.spec.index, options.run), out);
  }
  nlohmann::json j = diagnose::blind_json(options.run, style, rows, summary);
  j["summary"]["third_aims_met"] = diagnose::third_aims(summary).met();
  write_blind_check_files(dir, j, diagnose::blind_markdown(header, style, rows, summary), out);
}

}  // namespace

int run_third_selftest_command(const SelftestCommandOptions& options, std::ostream& out) {
  const auto start = std::chrono::steady_clock::now();
  const std::vector<diagnose::ThirdPairResult> results = diagnose::run_third_selftest(options.run);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const diagnose::BlindSummary summary = diagnose::summarise_third_selftest(results);
  const std::string header = diagnose::third_selftest_header(summary, options.run);
  out << diagnose::blind_terminal_report(
      header, diagnose::third_selftest_style(options.run),
      diagnose::blind_rows(diagnose::third_reality_for_check(), results), summary);
  const bool met = diagnose::third_aims(summary).met();
  out << fmt::format("seed {}: aims {} ({:.0f} s)\n", options.run.seed, met ? "met" : "MISSED",
                     seconds);
  if (options.out) write_third_files(options, header, results, summary, out);
  return met ? kExitOk : kExitFailure;
}

}  // namespace flange::cli
