// SPDX-License-Identifier: MIT
#include "third_selftest_report.h"

#include <fmt/format.h>

#include "pair_reality_style.h"

namespace flange::diagnose {
namespace {

std::string share(int part, int whole) {
  return whole == 0 ? "-" : fmt::format("{}/{} ({:.0f} %)", part, whole, 100.0 * part / whole);
}

std::string met(bool value) { return value ? "met" : "MISSED"; }

std::string split_class_table(const BlindSummary& s) {
  std::string text =
      "| class | alone | right top class (alone) | with others | right top class (with others) "
      "| class named (with others) |\n|---|---:|---:|---:|---:|---:|\n";
  for (const BlindClassRow& row : s.classes) {
    text += fmt::format("| {} | {} | {} | {} | {} | {} |\n", row.name, row.alone,
                        share(row.alone_top, row.alone), row.shared,
                        share(row.shared_top, row.shared), share(row.shared_named, row.shared));
  }
  return text;
}

std::string effects_table(const BlindSummary& s) {
  std::string text =
      "| true classes | pairs | explained | right top class | every class named | above-noise "
      "shrink (bias-type) | above-noise shrink (explained, bias-type) |\n"
      "|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const BlindEffectsRow& row : s.by_effects) {
    text +=
        fmt::format("| {} | {} | {} | {} | {} | {} | {} |\n", row.effects, row.cases, row.explained,
                    share(row.top_correct, row.cases), share(row.all_found, row.cases),
                    row.bias_cases > 0
                        ? fmt::format("{:.1f} % ({})", row.mean_excess_shrink_pct, row.bias_cases)
                        : std::string("-"),
                    row.explained_bias_cases > 0
                        ? fmt::format("{:.1f} % ({})", row.mean_explained_excess_shrink_pct,
                                      row.explained_bias_cases)
                        : std::string("-"));
  }
  text += fmt::format("| null and outside | {} | | | | | |\n", s.null_cases + s.outside_cases);
  return text;
}

std::string tables(const BlindSummary& s) {
  std::string text = "Pairs that hold the class alone and with others:\n\n" + split_class_table(s) +
                     "\nBy number of true classes:\n\n" + effects_table(s) + "\n";
  for (const std::string& line : third_aims_lines(third_aims(s))) text += line + "\n";
  return text;
}

std::vector<std::string> kind_lines(const BlindSummary& s) {
  return {fmt::format("null pairs: verdict 'none' in {} of {}; an effect claimed in {}",
                      s.null_none, s.null_cases, s.null_claims),
          fmt::format("outside the library: an effect claimed in {} of {}; verdict "
                      "'unexplained' in {}",
                      s.outside_claims, s.outside_cases, s.outside_unexplained)};
}

void add_case_json(const BlindRow& row, nlohmann::json& j) {
  j["fitted"] = findings_json(row.outcome->diagnosis.effects, true, true);
  j["partial"] = findings_json(row.outcome->partial, true, true);
}

}  // namespace

std::vector<std::string> third_aims_lines(const ThirdAims& a) {
  return {
      fmt::format("aim: right class first on >= 95 % of single-effect pairs: {}, {}",
                  share(a.singles_top, a.singles), met(a.singles_met)),
      fmt::format("aim: right class first on >= 90 % of two- and three-effect pairs: {}, {}",
                  share(a.multiples_top, a.multiples), met(a.multiples_top_met)),
      fmt::format("aim: every true class named on >= 85 % of two- and three-effect pairs: {}, {}",
                  share(a.multiples_all, a.multiples), met(a.multiples_all_met)),
      fmt::format("with a finding standing for the classes it names as indistinguishable from it: "
                  "right class first on {} of single-effect and {} of two- and three-effect "
                  "pairs, every true class among them on {}",
                  share(a.singles_top_among, a.singles), share(a.multiples_top_among, a.multiples),
                  share(a.multiples_all_among, a.multiples)),
      fmt::format("aim: nothing claimed on >= 95 % of null and outside pairs: {}, {}",
                  share(a.controls_quiet, a.controls), met(a.controls_met)),
      fmt::format("aim: held-out gap above the noise shrunk >= 80 % on explained bias-type pairs: "
                  "{:.1f} % over {}, {}",
                  a.explained_excess_shrink_pct, a.explained_bias, met(a.shrink_met))};
}

std::string third_selftest_header(const BlindSummary& summary, const SelftestOptions& options) {
  return fmt::format(
      "flange diagnose --selftest --reality third: {} pairs, seed {}; each a fitting and a "
      "held-out bench session of the third reality (effects defined by what they follow, shapes "
      "drawn per pair, one to three at 1.2-2x the noise, 6-100 Hz, a logger that drops rows and "
      "jitters){}; diagnosed blind",
      summary.cases, options.seed,
      options.duration_s > 0 ? fmt::format(", sessions capped at {:g} s", options.duration_s) : "");
}

BlindStyle third_selftest_style(const SelftestOptions& options) {
  BlindStyle style = pair_reality_style("third", "truth (size: effect RMS / noise; rate)",
                                        third_reality_for_check().aims(), options);
  style.kind_lines = kind_lines;
  style.add_case_json = add_case_json;
  style.extra_tables = tables;
  return style;
}

}  // namespace flange::diagnose
