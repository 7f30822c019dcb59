// SPDX-License-Identifier: MIT
#include "alt_selftest_report.h"

#include <fmt/format.h>

#include "alt_truth.h"
#include "claims_json.h"
#include "verdict_reasons.h"
#include "version.h"

namespace flange::diagnose {
namespace {

using alt_reality::AltPairKind;

bool in_library(const AltPairResult& r) {
  return r.spec.kind == AltPairKind::kSingle || r.spec.kind == AltPairKind::kDouble;
}

std::string describe_truth(const alt_reality::AltPairSpec& spec) {
  if (spec.truth.empty()) return "(nothing)";
  std::string text;
  for (const alt_reality::TruthEffect& e : spec.truth) {
    text += fmt::format("{}{}/{} ({:.1f}x noise)", text.empty() ? "" : " + ", e.draw.class_name,
                        e.draw.shape, e.rms_v / spec.fit.noise_v);
  }
  return text;
}

std::string join(const std::vector<std::string>& names) {
  if (names.empty()) return "-";
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + (n.empty() ? "?" : n);
  return text;
}

const char* yes_no(bool applies, bool value) {
  if (!applies) return "";
  return value ? "yes" : "no";
}

std::string nearest_cell(const AltPairResult& r) {
  if (r.diagnosis.status != Status::kUnexplained || r.score.nearest.empty()) return "";
  return fmt::format("{} {:.0f}%{}", r.score.nearest, r.score.nearest_shrink_pct,
                     in_library(r) ? (r.score.nearest_correct ? " (yes)" : " (no)") : "");
}

std::string percent(int part, int whole) {
  return whole == 0 ? "n/a" : fmt::format("{:.0f} %", 100.0 * part / whole);
}

nlohmann::json findings_json(const std::vector<EffectFinding>& findings) {
  nlohmann::json list = nlohmann::json::array();
  for (const EffectFinding& f : findings) {
    list.push_back({{"name", f.name},
                    {"params", f.params},
                    {"heldout_rms_after", f.heldout_rms_after},
                    {"inclusion", f.inclusion}});
  }
  return list;
}

nlohmann::json pair_json(const AltPairResult& r) {
  nlohmann::json j = alt_reality::alt_truth_json(r.spec);
  j["verdict"] = status_text(r.diagnosis.status);
  j["claimed_classes"] = r.score.claimed;
  j["nearest_class"] = r.score.nearest;
  j["nearest_shrink_pct"] = r.score.nearest_shrink_pct;
  j["verdict_correct"] = r.score.verdict_correct;
  if (in_library(r)) {
    j["top_correct"] = r.score.top_correct;
    j["all_found"] = r.score.all_found;
    j["nearest_correct"] = r.score.nearest_correct;
    j["spurious"] = r.score.spurious;
    j["bias_type"] = r.score.bias_type;
  }
  j["heldout_rms_before"] = r.diagnosis.heldout_rms_before;
  j["heldout_rms_after"] = r.diagnosis.heldout_rms_after;
  j["noise_std_v_estimated"] = r.diagnosis.noise_std_v;
  j["shrink_pct"] = r.score.shrink_pct;
  j["excess_shrink_pct"] = r.score.excess_shrink_pct;
  j["fitted"] = findings_json(r.diagnosis.effects);
  j["claims"] = claims_json(r.diagnosis.effects, r.score.claimed, r.score.claim_right);
  j["partial"] = findings_json(r.partial);
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace

std::string alt_selftest_header(const AltSummary& summary, const SelftestOptions& options) {
  return fmt::format(
      "flange diagnose --selftest --reality alt: {} pairs, seed {}; each a fitting and a held-out "
      "bench session of the alternative reality (its own protocols and effect formulas, 6-9 Hz, "
      "noise 0.01-0.1 V, clocks restarted at 0){}; diagnosed blind",
      summary.pairs, options.seed,
      options.duration_s > 0 ? fmt::format(", sessions capped at {:g} s", options.duration_s) : "");
}

std::string alt_terminal_table(const std::vector<AltPairResult>& results) {
  std::string text =
      fmt::format("{:>4}  {:<7}  {:<11}  {:<3}  {:<3}  {:>7}  {:>7}  {:>6}  {:<34}  {:<30}  {}\n",
                  "pair", "kind", "verdict", "top", "all", "shrink", "excess", "noise",
                  "classes named", "nearest (unexplained)", "truth");
  for (const AltPairResult& r : results) {
    const bool lib = in_library(r);
    text += fmt::format(
        "{:>4}  {:<7}  {:<11}  {:<3}  {:<3}  {:>6.1f}%  {:>6.1f}%  {:>6.3f}  {:<34}  {:<30}  {}\n",
        r.spec.index, alt_pair_kind_name(r.spec.kind), status_text(r.diagnosis.status),
        yes_no(lib, r.score.top_correct), yes_no(lib, r.score.all_found), r.score.shrink_pct,
        r.score.excess_shrink_pct, r.spec.fit.noise_v, join(r.score.claimed), nearest_cell(r),
        describe_truth(r.spec));
  }
  return text;
}

std::string alt_class_table(const AltSummary& summary) {
  std::string text =
      "| class | pairs | right top class | class named | above-noise shrink (bias-type pairs) |\n"
      "|---|---:|---:|---:|---:|\n";
  for (const AltClassRow& row : summary.classes) {
    text +=
        fmt::format("| {} | {} | {} | {} | {} |\n", row.name, row.pairs, row.top_correct, row.named,
                    row.bias_pairs > 0
                        ? fmt::format("{:.1f} % ({})", row.mean_excess_shrink_pct, row.bias_pairs)
                        : std::string("-"));
  }
  return text;
}

std::vector<std::string> alt_summary_lines(const AltSummary& s) {
  return {
      fmt::format("right top class: {}/{} in-library pairs ({}); aim >= 95 %: {}", s.top_correct,
                  s.in_library, percent(s.top_correct, s.in_library),
                  s.top_aim_met ? "met" : "MISSED"),
      fmt::format("all true classes named: {}/{} ({}); classes named that were not there: {}",
                  s.all_found, s.in_library, percent(s.all_found, s.in_library), s.spurious),
      fmt::format("partly explained in-library pairs: {}; of them the first class named was a "
                  "true one in {}",
                  s.partly_explained_in_library, s.partly_top_correct),
      fmt::format(
          "unexplained in-library pairs: {}; of them the nearest class was a true one in {}",
          s.unexplained_in_library, s.nearest_correct),
      fmt::format("mean held-out shrink, bias-type pairs ({}): {:.1f} % of the gap above the noise "
                  "(aim >= 80 %: {}); {:.1f} % of the gap RMS with the noise left in",
                  s.bias_type, s.mean_excess_shrink_pct, s.shrink_aim_met ? "met" : "MISSED",
                  s.mean_shrink_pct),
      fmt::format(
          "null pairs: verdict 'none' in {} of {} (aim >= 99 %: {}); an effect claimed in {}",
          s.null_none, s.null_pairs, s.none_aim_met ? "met" : "MISSED", s.null_claims),
      fmt::format("outside the library: an effect claimed in {} of {}; verdict 'unexplained' in {} "
                  "(aim: no claim on null or outside pairs: {})",
                  s.outside_claims, s.outside_pairs, s.outside_unexplained,
                  s.claims_aim_met ? "met" : "MISSED"),
  };
}

std::string alt_selftest_markdown(const std::string& header,
                                  const std::vector<AltPairResult>& results,
                                  const AltSummary& summary) {
  std::string md =
      header +
      "\n\n| pair | kind | truth (size: effect RMS / noise) | noise V | verdict | classes named | "
      "nearest (unexplained) | top | all | shrink % | above-noise shrink % |\n"
      "|---:|---|---|---:|---|---|---|---|---|---:|---:|\n";
  for (const AltPairResult& r : results) {
    const bool lib = in_library(r);
    md +=
        fmt::format("| {} | {} | {} | {:.3f} | {} | {} | {} | {} | {} | {:.1f} | {:.1f} |\n",
                    r.spec.index, alt_pair_kind_name(r.spec.kind), describe_truth(r.spec),
                    r.spec.fit.noise_v, status_text(r.diagnosis.status), join(r.score.claimed), nearest_cell(r),
                    yes_no(lib, r.score.top_correct), yes_no(lib, r.score.all_found),
                    r.score.shrink_pct, r.score.excess_shrink_pct);
  }
  md += "\nBy class (in-library pairs that hold it):\n\n" + alt_class_table(summary) + "\n";
  for (const std::string& line : alt_summary_lines(summary)) md += "- " + line + "\n";
  return md;
}

nlohmann::json alt_selftest_json(const SelftestOptions& options,
                                 const std::vector<AltPairResult>& results,
                                 const AltSummary& summary) {
  nlohmann::json j;
  j["generated_by"] = runtime::generated_by(
      options.only_case > 0
          ? fmt::format("flange diagnose --selftest --reality alt --case {} --seed {}",
                        options.only_case, options.seed)
          : fmt::format("flange diagnose --selftest --reality alt --pairs {} --seed {}",
                        summary.pairs, options.seed));
  j["reality"] = "alt";
  j["seed"] = options.seed;
  j["pairs"] = nlohmann::json::array();
  for (const AltPairResult& r : results) j["pairs"].push_back(pair_json(r));
  nlohmann::json classes = nlohmann::json::array();
  for (const AltClassRow& row : summary.classes) {
    classes.push_back({{"class", row.name},
                       {"pairs", row.pairs},
                       {"top_correct", row.top_correct},
                       {"named", row.named},
                       {"bias_pairs", row.bias_pairs},
                       {"mean_excess_shrink_pct", row.mean_excess_shrink_pct}});
  }
  j["summary"] = {{"in_library", summary.in_library},
                  {"top_correct", summary.top_correct},
                  {"all_found", summary.all_found},
                  {"spurious", summary.spurious},
                  {"partly_explained_in_library", summary.partly_explained_in_library},
                  {"partly_top_correct", summary.partly_top_correct},
                  {"unexplained_in_library", summary.unexplained_in_library},
                  {"nearest_correct", summary.nearest_correct},
                  {"bias_type", summary.bias_type},
                  {"mean_shrink_pct", summary.mean_shrink_pct},
                  {"mean_excess_shrink_pct", summary.mean_excess_shrink_pct},
                  {"null_pairs", summary.null_pairs},
                  {"null_none", summary.null_none},
                  {"null_claims", summary.null_claims},
                  {"outside_pairs", summary.outside_pairs},
                  {"outside_claims", summary.outside_claims},
                  {"by_class", classes},
                  {"aims_met", summary.aims_met()}};
  return j;
}

}  // namespace flange::diagnose
