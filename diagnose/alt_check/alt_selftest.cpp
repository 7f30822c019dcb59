// SPDX-License-Identifier: MIT
#include "alt_selftest.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "alt_classes.h"
#include "diagnosis_detail.h"
#include "finding_class.h"
#include "parallel_cases.h"
#include "series_statistics.h"

namespace flange::diagnose {
namespace {

using alt_reality::AltPairKind;
using alt_reality::AltPairSpec;

bool in_library(const AltPairSpec& spec) {
  return spec.kind == AltPairKind::kSingle || spec.kind == AltPairKind::kDouble;
}

bool holds_class(const AltPairSpec& spec, const std::string& name) {
  return std::any_of(spec.truth.begin(), spec.truth.end(),
                     [&](const auto& e) { return e.draw.class_name == name; });
}

std::string fmt_label(int index, const char* part) {
  return fmt::format("alt pair {} ({})", index, part);
}

void score_in_library(const AltPairSpec& spec, const Diagnosis& diagnosis, AltScore& score) {
  score.verdict_correct = diagnosis.status == "explained";
  score.top_correct = !score.claimed.empty() && holds_class(spec, score.claimed.front());
  score.all_found = std::all_of(spec.truth.begin(), spec.truth.end(), [&](const auto& e) {
    return std::find(score.claimed.begin(), score.claimed.end(), e.draw.class_name) !=
           score.claimed.end();
  });
  score.nearest_correct = diagnosis.status == "unexplained" && !score.nearest.empty() &&
                          holds_class(spec, score.nearest);
  score.bias_type = std::all_of(spec.truth.begin(), spec.truth.end(), [](const auto& e) {
    return alt_reality::alt_class(e.draw.class_name).bias_type;
  });
}

}  // namespace

RecordingSeries alt_series(const alt_reality::AltRecording& r, const alt_reality::SessionPlan& plan,
                           const std::string& label) {
  RecordingSeries s;
  s.path = label;
  s.start_utc_s = alt_session_start_utc_s(plan);
  s.t_s = r.t_s;
  s.clearance_mm = r.clearance_mm;
  s.temp_c = r.temp_c;
  s.voltage_v = r.voltage_v;
  return s;
}

double alt_session_start_utc_s(const alt_reality::SessionPlan& plan) {
  // When the alternative reality's sensor was calibrated (its age 0): any date serves, only the
  // difference between two sessions' starts is used.
  constexpr double kSensorCalibratedUtcS = 1767225600.0;  // 2026-01-01T00:00:00Z
  return kSensorCalibratedUtcS + plan.start_age_s;
}

AltScore score_alt_pair(const AltPairSpec& spec, const Diagnosis& diagnosis,
                        const std::vector<EffectFinding>& partial) {
  AltScore score;
  // A partly explained verdict names its effects as found: they are claims too.
  if (diagnosis.status == "explained" || diagnosis.status == "partly explained") {
    for (const EffectFinding& f : diagnosis.effects) score.claimed.push_back(class_of_finding(f));
  }
  if (diagnosis.status == "unexplained") {
    const EffectFinding* nearest = diagnosis.nearest  ? &*diagnosis.nearest
                                   : !partial.empty() ? &partial.front()
                                                      : nullptr;
    if (nearest != nullptr) {
      score.nearest = class_of_finding(*nearest);
      score.nearest_shrink_pct = nearest->shrink_pct;
    }
  }
  for (const std::string& c : score.claimed) {
    score.claim_right.push_back(holds_class(spec, c));
    score.spurious += holds_class(spec, c) ? 0 : 1;
  }
  if (in_library(spec)) {
    score_in_library(spec, diagnosis, score);
  } else {
    score.verdict_correct =
        diagnosis.status == (spec.kind == AltPairKind::kNull ? "none" : "unexplained");
  }
  const double before = diagnosis.heldout_rms_before, after = diagnosis.heldout_rms_after;
  if (before > 0.0) score.shrink_pct = 100.0 * (before - after) / before;
  const double sigma = spec.heldout.noise_v;
  const double excess_before = rms_above_noise(before, sigma);
  if (excess_before > 0.0) {
    score.excess_shrink_pct = 100.0 * (1.0 - rms_above_noise(after, sigma) / excess_before);
  }
  return score;
}

std::vector<AltPairResult> run_alt_selftest(const SelftestOptions& options) {
  const int count = options.only_case > 0 ? 1 : options.cases;
  std::vector<AltPairResult> results(static_cast<std::size_t>(count));
  run_in_parallel(count, options.jobs, [&](int i) {
    const auto start = std::chrono::steady_clock::now();
    AltPairResult& r = results[static_cast<std::size_t>(i)];
    const int index = options.only_case > 0 ? options.only_case : i + 1;
    r.spec = alt_reality::draw_alt_pair(index, options.seed, options.duration_s);
    alt_reality::AltPair pair = alt_reality::render_alt_pair(r.spec);
    // Blind: the two recordings and their start times only, as `flange diagnose --real A
    // --holdout B --real-start S --holdout-start S` reads them.
    DiagnoseOptions diagnose_options;
    diagnose_options.bootstrap_rounds = options.bootstrap_rounds;
    diagnose_options.seed = options.seed + static_cast<std::uint64_t>(index);
    DiagnosisResult detailed = diagnose_in_detail(
        alt_series(pair.fit, r.spec.fit, fmt_label(index, "fit")),
        alt_series(pair.heldout, r.spec.heldout, fmt_label(index, "held-out")), diagnose_options);
    r.diagnosis = std::move(detailed.diagnosis);
    r.partial = std::move(detailed.detail.partial);
    r.score = score_alt_pair(r.spec, r.diagnosis, r.partial);
    if (options.only_case > 0) r.pair = std::move(pair);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  });
  return results;
}

}  // namespace flange::diagnose
