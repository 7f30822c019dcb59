// SPDX-License-Identifier: MIT
#include "diagnose_third_selftest_command.h"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <stdexcept>

#include "cli.h"
#include "third_selftest_report.h"
#include "third_truth.h"
#include "utc_time.h"

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
    const std::vector<fs::path> paths =
        third_reality::write_third_pair(dir, first.spec, *first.sessions);
    for (const fs::path& path : paths) out << "  wrote " << path.string() << "\n";
    out << fmt::format(
        "  the same diagnosis: flange diagnose --real {} --holdout {} --real-start {} "
        "--holdout-start {} --out DIR\n",
        paths[0].string(), paths[1].string(),
        format_utc_time(diagnose::third_session_start_utc_s(first.spec.fit)),
        format_utc_time(diagnose::third_session_start_utc_s(first.spec.heldout)));
  }
  std::ofstream json(dir / "selftest.json", std::ios::binary);
  nlohmann::json j = diagnose::blind_json(options.run, style, rows, summary);
  j["summary"]["third_aims_met"] = diagnose::third_aims(summary).met();
  json << j.dump(2) << "\n";
  std::ofstream md(dir / "selftest.md", std::ios::binary);
  md << diagnose::blind_markdown(header, style, rows, summary);
  json.close();
  md.close();
  if (!json || !md) throw std::runtime_error(dir.string() + ": cannot write");
  out << "  wrote " << (dir / "selftest.json").string() << " and " << (dir / "selftest.md").string()
      << "\n";
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
