// SPDX-License-Identifier: MIT
// What `flange diagnose --selftest` shows of a blind check (blind_check.h), for either reality:
// the terminal table, the table by class, the summary against the aims, selftest.md and
// selftest.json. What differs between the realities' reports is data of their BlindStyle.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "blind_check.h"

namespace flange::diagnose {

struct BlindStyle {
  std::string noun;       // "case" or "pair": the index column, the JSON list and its counts
  std::string command;    // "flange diagnose --selftest ..." (generated_by, with --case or --cases)
  std::string item;       // "effect" or "class": what a claim names
  std::string items;      // its plural
  std::string top_label;  // the summary's first line: "correct top effect", ...
  std::string named_title;     // the column of the effects named
  int named_width = 40;        // its width in the terminal
  std::string truth_title;     // the truth's column in selftest.md
  std::string claimed_key;     // the claims' key in selftest.json
  bool shows_noise = false;    // a column of the fitting session's noise
  bool shows_nearest = false;  // the nearest effect of an unexplained verdict: a column,
                               // its counts in the summary and in selftest.json
  BlindAims aims;              // as the summary lines state them
  nlohmann::json run_json;     // the run's fields of selftest.json besides generated_by
  // The summary's lines on the null and outside cases, as the reality's aims read them.
  std::function<std::vector<std::string>(const BlindSummary&)> kind_lines;
  // A case's fields of selftest.json beyond the harness's (its fits, what the candidates got).
  std::function<void(const BlindRow&, nlohmann::json&)> add_case_json;
  // Tables after the table by class (Markdown; none when unset).
  std::function<std::string(const BlindSummary&)> extra_tables;
};

// The header line, the table of cases (and by class, when the reality has classes) and the
// summary lines: what the terminal shows.
std::string blind_terminal_report(const std::string& header, const BlindStyle& style,
                                  const std::vector<BlindRow>& rows, const BlindSummary& summary);
// The summary against the aims, one line each (shared by the terminal and selftest.md).
std::vector<std::string> blind_summary_lines(const BlindStyle& style, const BlindSummary& summary);
// selftest.md: the header, the table, the table by class and the summary.
std::string blind_markdown(const std::string& header, const BlindStyle& style,
                           const std::vector<BlindRow>& rows, const BlindSummary& summary);
// selftest.json: every case with its truth, verdict, score and fits, and the summary.
nlohmann::json blind_json(const SelftestOptions& options, const BlindStyle& style,
                          const std::vector<BlindRow>& rows, const BlindSummary& summary);

// Findings as selftest.json lists them: name and parameters, and the held-out RMS they leave
// and the inclusion share when asked.
nlohmann::json findings_json(const std::vector<EffectFinding>& findings, bool heldout_rms,
                             bool inclusion);
// [{"class", "confidence", "right"}] for each claim, `effects` in the verdict's order and
// `claimed` (the class each names) with `right` beside it: what
// bench/confidence_reliability.sh gathers into the reliability table.
nlohmann::json claims_json(const std::vector<EffectFinding>& effects,
                           const std::vector<std::string>& claimed, const std::vector<bool>& right);

}  // namespace flange::diagnose
