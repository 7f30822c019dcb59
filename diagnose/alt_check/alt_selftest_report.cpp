// SPDX-License-Identifier: MIT
#include "alt_selftest_report.h"

#include <fmt/format.h>

#include "pair_reality_style.h"

namespace flange::diagnose {
namespace {

std::vector<std::string> kind_lines(const AltSummary& s) {
  return {
      fmt::format(
          "null pairs: verdict 'none' in {} of {} (aim >= 99 %: {}); an effect claimed in {}",
          s.null_none, s.null_cases, s.none_aim_met ? "met" : "MISSED", s.null_claims),
      fmt::format("outside the library: an effect claimed in {} of {}; verdict 'unexplained' in {} "
                  "(aim: no claim on null or outside pairs: {})",
                  s.outside_claims, s.outside_cases, s.outside_unexplained,
                  s.claims_aim_met ? "met" : "MISSED"),
  };
}

// The fits and what the candidates got, each with the held-out RMS it leaves and its share.
void add_case_json(const BlindRow& row, nlohmann::json& j) {
  j["fitted"] = findings_json(row.outcome->diagnosis.effects, true, true);
  j["partial"] = findings_json(row.outcome->partial, true, true);
}

}  // namespace

std::string alt_selftest_header(const AltSummary& summary, const SelftestOptions& options) {
  return fmt::format(
      "flange diagnose --selftest --reality alt: {} pairs, seed {}; each a fitting and a held-out "
      "bench session of the alternative reality (its own protocols and effect formulas, 6-9 Hz, "
      "noise 0.01-0.1 V, clocks restarted at 0){}; diagnosed blind",
      summary.cases, options.seed,
      options.duration_s > 0 ? fmt::format(", sessions capped at {:g} s", options.duration_s) : "");
}

BlindStyle alt_selftest_style(const SelftestOptions& options) {
  BlindStyle style = pair_reality_style("alt", "truth (size: effect RMS / noise)",
                                        alt_reality_for_check().aims(), options);
  style.kind_lines = kind_lines;
  style.add_case_json = add_case_json;
  return style;
}

}  // namespace flange::diagnose
