// SPDX-License-Identifier: MIT
// What `flange diagnose --selftest --reality alt` shows: the seed line, one row per pair, the
// table by class, the summary against the aims, selftest.json and selftest.md.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "alt_selftest.h"

namespace flange::diagnose {

// The first line: pairs, seed, what a pair is.
std::string alt_selftest_header(const AltSummary& summary, const SelftestOptions& options);
// One row per pair: kind, verdict, top/all/nearest, shrinks, noise, classes named, the truth.
std::string alt_terminal_table(const std::vector<AltPairResult>& results);
// The rows by class (in-library pairs that hold the class).
std::string alt_class_table(const AltSummary& summary);
// The summary against the aims, one line each.
std::vector<std::string> alt_summary_lines(const AltSummary& summary);
// selftest.md: header, the pairs, the classes, the summary.
std::string alt_selftest_markdown(const std::string& header,
                                  const std::vector<AltPairResult>& results,
                                  const AltSummary& summary);
// selftest.json: every pair with its truth (the sidecar's content), verdict and fits.
nlohmann::json alt_selftest_json(const SelftestOptions& options,
                                 const std::vector<AltPairResult>& results,
                                 const AltSummary& summary);

}  // namespace flange::diagnose
