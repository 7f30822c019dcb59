// SPDX-License-Identifier: MIT
#include "selftest_report.h"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "bench_scenario.h"
#include "claims_json.h"
#include "recording_writer.h"
#include "verdict_reasons.h"
#include "version.h"

namespace flange::diagnose {
namespace {

std::string describe_truth(const SelftestCaseSpec& spec) {
  if (spec.kind == SelftestKind::kNull) return "(nothing)";
  if (spec.kind == SelftestKind::kOutside) return spec.outside.describe();
  std::string text;
  for (const sim::EffectSettings& e : spec.truth) {
    std::string params;
    for (const auto& [key, value] : e.params) {
      params += fmt::format("{}{}={:.3g}", params.empty() ? "" : ", ", key, value);
    }
    text += fmt::format("{}{}({})", text.empty() ? "" : " + ", e.name, params);
  }
  return text;
}

std::string join(const std::vector<std::string>& names) {
  if (names.empty()) return "-";
  std::string text;
  for (const std::string& n : names) text += (text.empty() ? "" : ", ") + n;
  return text;
}

const char* yes_no(bool in_library, bool value) {
  if (!in_library) return "";
  return value ? "yes" : "no";
}

bool in_library(const SelftestCaseSpec& spec) {
  return spec.kind == SelftestKind::kSingle || spec.kind == SelftestKind::kPair;
}

std::string percent(int part, int whole) {
  return whole == 0 ? "n/a" : fmt::format("{:.0f} %", 100.0 * part / whole);
}

nlohmann::json case_json(const SelftestCaseResult& r) {
  nlohmann::json truth = nlohmann::json::array();
  for (const sim::EffectSettings& e : r.spec.truth) {
    truth.push_back({{"name", e.name}, {"params", e.params}});
  }
  nlohmann::json j = {
      {"case", r.spec.index},
      {"kind", selftest_kind_name(r.spec.kind)},
      {"truth", truth},
      {"verdict", status_text(r.diagnosis.status)},
      {"claimed", r.score.claimed},
      {"verdict_correct", r.score.verdict_correct},
      {"heldout_rms_before", r.diagnosis.heldout_rms_before},
      {"heldout_rms_after", r.diagnosis.heldout_rms_after},
      {"noise_std_v_estimated", r.diagnosis.noise_std_v},
      {"shrink_pct", r.score.shrink_pct},
      {"excess_shrink_pct", r.score.excess_shrink_pct},
      {"seconds", r.seconds},
  };
  if (r.spec.kind == SelftestKind::kOutside) {
    j["outside"] = {{"name", r.spec.outside.name},
                    {"value", r.spec.outside.value},
                    {"at_fraction", r.spec.outside.at_fraction}};
  }
  if (in_library(r.spec)) {
    j["top_correct"] = r.score.top_correct;
    j["all_found"] = r.score.all_found;
    j["spurious"] = r.score.spurious;
    j["bias_type"] = r.score.bias_type;
  }
  nlohmann::json fitted = nlohmann::json::array();
  for (const EffectFinding& f : r.diagnosis.effects) {
    fitted.push_back({{"name", f.name}, {"params", f.params}, {"inclusion", f.inclusion}});
  }
  j["fitted"] = fitted;
  j["claims"] = claims_json(r.diagnosis.effects, r.score.claimed, r.score.claim_right);
  nlohmann::json partial = nlohmann::json::array();
  for (const EffectFinding& f : r.partial) {
    partial.push_back(
        {{"name", f.name}, {"params", f.params}, {"heldout_rms_after", f.heldout_rms_after}});
  }
  j["partial"] = partial;
  if (r.diagnosis.nearest) {
    j["nearest"] = {{"name", r.diagnosis.nearest->name},
                    {"params", r.diagnosis.nearest->params},
                    {"shrink_pct", r.diagnosis.nearest->shrink_pct}};
  }
  return j;
}

}  // namespace

std::vector<std::string> selftest_summary_lines(const SelftestSummary& s) {
  return {
      fmt::format("correct top effect: {}/{} in-library cases ({}); aim >= 90 %: {}", s.top_correct,
                  s.in_library, percent(s.top_correct, s.in_library),
                  s.top_aim_met ? "met" : "MISSED"),
      fmt::format("all true effects named: {}/{} ({}); effects named that were not there: {}",
                  s.all_found, s.in_library, percent(s.all_found, s.in_library), s.spurious),
      fmt::format("mean held-out shrink, bias-type cases ({}): {:.1f} % of the gap above the "
                  "noise (aim >= 70 %: {}); {:.1f} % of the gap RMS with the noise left in",
                  s.bias_type, s.mean_excess_shrink_pct, s.shrink_aim_met ? "met" : "MISSED",
                  s.mean_shrink_pct),
      fmt::format("null cases: {} with an effect claimed of {} (aim: none: {}); verdict 'none' "
                  "in {}",
                  s.null_claims, s.null_cases, s.null_aim_met ? "met" : "MISSED", s.null_correct),
      fmt::format("outside the library: {} with an effect claimed of {}; verdict 'unexplained' "
                  "in {}",
                  s.outside_claims, s.outside_cases, s.outside_correct),
  };
}

std::string selftest_header(const SelftestSummary& summary, std::uint64_t seed, double duration_s) {
  return fmt::format(
      "flange diagnose --selftest: {} cases, seed {}; each a calibration and a held-out bench "
      "session of {:g} s at 6 Hz, twin noise {:.4g} V; diagnosed blind",
      summary.cases, seed, duration_s, sim::kThesisRepeatabilityRmsV);
}

std::string selftest_terminal_table(const std::vector<SelftestCaseResult>& results) {
  std::string text =
      fmt::format("{:>4}  {:<7}  {:<11}  {:<3}  {:<3}  {:>7}  {:>7}  {:<40}  {}\n", "case", "kind",
                  "verdict", "top", "all", "shrink", "excess", "named", "truth");
  for (const SelftestCaseResult& r : results) {
    const bool lib = in_library(r.spec);
    text += fmt::format("{:>4}  {:<7}  {:<11}  {:<3}  {:<3}  {:>6.1f}%  {:>6.1f}%  {:<40}  {}\n",
                        r.spec.index, selftest_kind_name(r.spec.kind), status_text(r.diagnosis.status),
                        yes_no(lib, r.score.top_correct), yes_no(lib, r.score.all_found),
                        r.score.shrink_pct, r.score.excess_shrink_pct, join(r.score.claimed),
                        describe_truth(r.spec));
  }
  return text;
}

std::string selftest_markdown(const std::string& header,
                              const std::vector<SelftestCaseResult>& results,
                              const SelftestSummary& summary) {
  std::string md = header + "\n\n" +
                   "| case | kind | truth | verdict | named | top | all | shrink % | above-noise "
                   "shrink % |\n|---:|---|---|---|---|---|---|---:|---:|\n";
  for (const SelftestCaseResult& r : results) {
    const bool lib = in_library(r.spec);
    md +=
        fmt::format("| {} | {} | {} | {} | {} | {} | {} | {:.1f} | {:.1f} |\n", r.spec.index,
                    selftest_kind_name(r.spec.kind), describe_truth(r.spec), status_text(r.diagnosis.status),
                    join(r.score.claimed), yes_no(lib, r.score.top_correct),
                    yes_no(lib, r.score.all_found), r.score.shrink_pct, r.score.excess_shrink_pct);
  }
  md += "\n";
  for (const std::string& line : selftest_summary_lines(summary)) md += "- " + line + "\n";
  return md;
}

nlohmann::json selftest_json(const SelftestOptions& options,
                             const std::vector<SelftestCaseResult>& results,
                             const SelftestSummary& summary, double duration_s) {
  nlohmann::json j;
  j["generated_by"] = runtime::generated_by(
      options.only_case > 0 ? fmt::format("flange diagnose --selftest --case {} --seed {}",
                                          options.only_case, options.seed)
                            : fmt::format("flange diagnose --selftest --cases {} --seed {}",
                                          summary.cases, options.seed));
  j["duration_s"] = duration_s;
  j["cases"] = nlohmann::json::array();
  for (const SelftestCaseResult& r : results) j["cases"].push_back(case_json(r));
  j["summary"] = {
      {"in_library", summary.in_library},
      {"top_correct", summary.top_correct},
      {"all_found", summary.all_found},
      {"spurious", summary.spurious},
      {"bias_type", summary.bias_type},
      {"mean_shrink_pct", summary.mean_shrink_pct},
      {"mean_excess_shrink_pct", summary.mean_excess_shrink_pct},
      {"null_cases", summary.null_cases},
      {"null_claims", summary.null_claims},
      {"outside_cases", summary.outside_cases},
      {"outside_claims", summary.outside_claims},
      {"aims_met", summary.aims_met()},
  };
  return j;
}

std::vector<std::filesystem::path> write_selftest_recordings(const std::filesystem::path& dir,
                                                             int case_index,
                                                             const SelftestRecordings& recordings) {
  std::vector<std::filesystem::path> written;
  for (const auto& [name, series] : {std::pair{"calibration", &recordings.calibration},
                                     std::pair{"heldout", &recordings.heldout}}) {
    const auto path = dir / fmt::format("case_{}_{}.csv", case_index, name);
    std::ofstream csv(path, std::ios::binary);
    sim::RecordingWriter writer(csv);
    for (std::size_t i = 0; i < series->size(); ++i) {
      writer.write({series->t_s[i], series->clearance_mm[i], series->temp_c[i]},
                   {series->t_s[i], series->temp_c[i], series->voltage_v[i]});
    }
    csv.close();
    if (!csv) throw std::runtime_error(path.string() + ": cannot write");
    written.push_back(path);
  }
  return written;
}

}  // namespace flange::diagnose
