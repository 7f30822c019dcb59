// SPDX-License-Identifier: MIT
#include "diagnose_selftest_command.h"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "bench_scenario.h"
#include "cli.h"
#include "diagnose_alt_selftest_command.h"
#include "diagnose_memory.h"
#include "diagnose_third_selftest_command.h"
#include "input_error.h"
#include "selftest_report.h"

namespace flange::cli {
namespace fs = std::filesystem;

namespace {

// selftest.json, selftest.md and, for one case, its two sessions; throws std::runtime_error.
void write_selftest_files(const SelftestCommandOptions& options, const std::string& header,
                          const std::vector<diagnose::SelftestCaseResult>& results,
                          const diagnose::SelftestSummary& summary,
                          const diagnose::BlindStyle& style, std::ostream& out) {
  const fs::path dir(*options.out);
  fs::create_directories(dir);
  if (results.front().sessions) {
    for (const fs::path& path : diagnose::write_selftest_recordings(dir, options.run.only_case,
                                                                    *results.front().sessions)) {
      out << "  wrote " << path.string() << "\n";
    }
  }
  std::ofstream json(dir / "selftest.json", std::ios::binary);
  const std::vector<diagnose::BlindRow> rows =
      diagnose::blind_rows(diagnose::twin_reality(), results);
  json << diagnose::blind_json(options.run, style, rows, summary).dump(2) << "\n";
  std::ofstream md(dir / "selftest.md", std::ios::binary);
  md << diagnose::blind_markdown(header, style, rows, summary);
  json.close();
  md.close();
  if (!json || !md) throw std::runtime_error(dir.string() + ": cannot write");
  out << "  wrote " << (dir / "selftest.json").string() << " and " << (dir / "selftest.md").string()
      << "\n";
}

}  // namespace

void add_selftest_options(CLI::App& diagnose, SelftestCommandOptions& options) {
  diagnose.add_flag("--selftest", options.selftest,
                    "blind check: simulated bench sessions with random, undisclosed effects");
  diagnose
      .add_option("--reality", options.reality,
                  "--selftest: whose sessions: twin (the sensor twin's), alt (the alternative "
                  "reality's, diagnose/alt_reality/) or third (the third reality's, shapes drawn "
                  "per pair, diagnose/third_reality/)")
      ->default_val("twin")
      ->check(CLI::IsMember({"twin", "alt", "third"}));
  diagnose
      .add_option("--cases,--pairs", options.run.cases,
                  "--selftest: number of cases (pairs of sessions), 1 to 1000")
      ->default_val(10)
      ->check(CLI::Range(1, 1000));
  diagnose
      .add_option("--case", options.run.only_case,
                  "--selftest: run only case K of the seed (one row of a table), 1 to 1000")
      ->check(CLI::Range(1, 1000));
  diagnose
      .add_option("--duration", options.run.duration_s,
                  "--selftest: seconds per bench session, 600 to 6600 (default: the protocol's "
                  "own; --reality alt: a cap on its 3600-6600; third: on its 2400-5400)")
      ->check(CLI::Range(600.0, 6600.0));
  diagnose
      .add_option("--jobs", options.run.jobs,
                  "worker threads of the diagnosis (with --selftest, its cases run on them), 1 "
                  "to 64 (default: the machine's cores)")
      ->check(CLI::Range(1, 64));
}

int run_selftest_command(const SelftestCommandOptions& options, std::ostream& out) {
  keep_freed_memory_for_reuse();
  if (options.reality == "alt") return run_alt_selftest_command(options, out);
  if (options.reality == "third") return run_third_selftest_command(options, out);
  const auto start = std::chrono::steady_clock::now();
  const std::vector<diagnose::SelftestCaseResult> results = diagnose::run_selftest(options.run);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const diagnose::SelftestSummary summary = diagnose::summarise_selftest(results);
  const double duration =
      options.run.duration_s > 0 ? options.run.duration_s : sim::BenchProtocol{}.duration_s;

  const std::string header = diagnose::selftest_header(summary, options.run.seed, duration);
  const diagnose::BlindStyle style = diagnose::selftest_style(duration);
  out << diagnose::blind_terminal_report(
      header, style, diagnose::blind_rows(diagnose::twin_reality(), results), summary);
  out << fmt::format("aims {} ({:.0f} s)\n", summary.aims_met() ? "met" : "MISSED", seconds);
  if (options.out) write_selftest_files(options, header, results, summary, style, out);
  return summary.aims_met() ? kExitOk : kExitFailure;
}

}  // namespace flange::cli
