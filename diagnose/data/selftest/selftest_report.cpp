// SPDX-License-Identifier: MIT
#include "selftest_report.h"

#include <fmt/format.h>

#include <fstream>
#include <stdexcept>

#include "bench_scenario.h"
#include "recording_writer.h"

namespace flange::diagnose {
namespace {

std::vector<std::string> kind_lines(const SelftestSummary& s) {
  return {
      fmt::format("null cases: {} with an effect claimed of {} (aim: none: {}); verdict 'none' "
                  "in {}",
                  s.null_claims, s.null_cases, s.claims_aim_met ? "met" : "MISSED", s.null_none),
      fmt::format("outside the library: {} with an effect claimed of {}; verdict 'unexplained' "
                  "in {}",
                  s.outside_claims, s.outside_cases, s.outside_unexplained),
  };
}

// The fits, what the candidates got and the nearest effect of an unexplained verdict.
void add_case_json(const BlindRow& row, nlohmann::json& j) {
  const Diagnosis& d = row.outcome->diagnosis;
  j["fitted"] = findings_json(d.effects, false, true);
  j["partial"] = findings_json(row.outcome->partial, true, false);
  if (d.nearest) {
    j["nearest"] = {{"name", d.nearest->name},
                    {"params", d.nearest->params},
                    {"shrink_pct", d.nearest->shrink_pct}};
  }
}

}  // namespace

std::string selftest_header(const SelftestSummary& summary, std::uint64_t seed, double duration_s) {
  return fmt::format(
      "flange diagnose --selftest: {} cases, seed {}; each a calibration and a held-out bench "
      "session of {:g} s at 6 Hz, twin noise {:.4g} V; diagnosed blind",
      summary.cases, seed, duration_s, sim::kThesisRepeatabilityRmsV);
}

BlindStyle selftest_style(double duration_s) {
  BlindStyle style;
  style.noun = "case";
  style.command = "flange diagnose --selftest";
  style.item = "effect";
  style.items = "effects";
  style.top_label = "correct top effect";
  style.named_title = "named";
  style.named_width = 40;
  style.truth_title = "truth";
  style.claimed_key = "claimed";
  style.aims = twin_reality().aims();
  style.run_json = {{"duration_s", duration_s}};
  style.kind_lines = kind_lines;
  style.add_case_json = add_case_json;
  return style;
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
