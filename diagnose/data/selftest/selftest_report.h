// SPDX-License-Identifier: MIT
// What `flange diagnose --selftest` shows of a blind check (diagnose_selftest.h): the terminal
// table, the summary against the aims, selftest.json and selftest.md (the table as
// docs/diagnose_figures.md records it), and a single case's two sessions as recordings.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "diagnose_selftest.h"

namespace flange::diagnose {

// The first line: cases, seed, session length and the twin's noise.
std::string selftest_header(const SelftestSummary& summary, std::uint64_t seed, double duration_s);
// One row per case: kind, verdict, top/all correct, shrinks, named effects and the truth.
std::string selftest_terminal_table(const std::vector<SelftestCaseResult>& results);
// The summary against the aims, one line each (shared by the terminal and selftest.md).
std::vector<std::string> selftest_summary_lines(const SelftestSummary& summary);
// selftest.md: the header, the table and the summary.
std::string selftest_markdown(const std::string& header,
                              const std::vector<SelftestCaseResult>& results,
                              const SelftestSummary& summary);
// selftest.json: every case with its truth, verdict and fits, and the summary.
nlohmann::json selftest_json(const SelftestOptions& options,
                             const std::vector<SelftestCaseResult>& results,
                             const SelftestSummary& summary, double duration_s);
// DIR/case_K_calibration.csv and DIR/case_K_heldout.csv, for `flange diagnose --real ...
// --holdout ...`. Throws std::runtime_error naming a file that cannot be written.
std::vector<std::filesystem::path> write_selftest_recordings(const std::filesystem::path& dir,
                                                             int case_index,
                                                             const SelftestRecordings& recordings);

}  // namespace flange::diagnose
