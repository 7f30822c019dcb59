// SPDX-License-Identifier: MIT
#include "alt_selftest.h"

#include <fmt/format.h>

#include <algorithm>

#include "alt_classes.h"
#include "alt_truth.h"
#include "finding_class.h"

namespace flange::diagnose {
namespace {

using alt_reality::AltPairKind;
using alt_reality::AltPairSpec;

BlindKind blind_kind(AltPairKind kind) {
  switch (kind) {
    case AltPairKind::kSingle:
      return BlindKind::kSingle;
    case AltPairKind::kDouble:
      return BlindKind::kPair;
    case AltPairKind::kNull:
      return BlindKind::kNull;
    case AltPairKind::kOutside:
      return BlindKind::kOutside;
  }
  return BlindKind::kNull;
}

// Scored above the held-out session's true noise.
BlindTruth truth_of(const AltPairSpec& spec) {
  BlindTruth truth;
  truth.kind = blind_kind(spec.kind);
  for (const alt_reality::TruthEffect& e : spec.truth) truth.classes.push_back(e.draw.class_name);
  truth.bias_type = in_library(truth.kind) &&
                    std::all_of(spec.truth.begin(), spec.truth.end(), [](const auto& e) {
                      return alt_reality::alt_class(e.draw.class_name).bias_type;
                    });
  truth.noise_std_v = spec.heldout.noise_v;
  return truth;
}

std::string describe_truth(const AltPairSpec& spec) {
  if (spec.truth.empty()) return "(nothing)";
  std::string text;
  for (const alt_reality::TruthEffect& e : spec.truth) {
    text += fmt::format("{}{}/{} ({:.1f}x noise)", text.empty() ? "" : " + ", e.draw.class_name,
                        e.draw.shape, e.rms_v / spec.fit.noise_v);
  }
  return text;
}

std::string fmt_label(int index, const char* part) {
  return fmt::format("alt pair {} ({})", index, part);
}

class AltReality : public BlindReality<AltPairSpec, alt_reality::AltPair> {
 public:
  AltPairSpec draw(int index, const SelftestOptions& options) const override {
    return alt_reality::draw_alt_pair(index, options.seed, options.duration_s);
  }
  alt_reality::AltPair record(const AltPairSpec& spec, const SelftestOptions&) const override {
    return alt_reality::render_alt_pair(spec);
  }
  // Blind: the two recordings and their start times only, as `flange diagnose --real A
  // --holdout B --real-start S --holdout-start S` reads them.
  BlindSessions as_recordings(const AltPairSpec& spec,
                              const alt_reality::AltPair& pair) const override {
    return {alt_series(pair.fit, spec.fit, fmt_label(spec.index, "fit")),
            alt_series(pair.heldout, spec.heldout, fmt_label(spec.index, "held-out"))};
  }
  BlindScore score(const AltPairSpec& spec, const BlindOutcome& outcome,
                   const alt_reality::AltPair&) const override {
    return score_alt_pair(spec, outcome.diagnosis, outcome.partial);
  }
  BlindRow row(const AltPairSpec& spec) const override {
    BlindRow row;
    row.index = spec.index;
    row.truth = truth_of(spec);
    row.kind_name = alt_pair_kind_name(spec.kind);
    row.truth_text = describe_truth(spec);
    row.noise_v = spec.fit.noise_v;
    row.truth_json = alt_reality::alt_truth_json(spec);
    return row;
  }
  // The aims: >= 95 % right top class, >= 80 % mean shrink of the above-noise gap for
  // bias-type classes, no effect claimed on null or outside pairs, "none" on >= 99 % of nulls.
  BlindAims aims() const override { return {95, 80.0, true, 99}; }
  std::vector<std::string> class_names() const override {
    std::vector<std::string> names;
    for (const alt_reality::AltClass& c : alt_reality::alt_classes()) names.push_back(c.name);
    return names;
  }
};

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
  return score_blind(truth_of(spec), diagnosis, partial, class_of_finding);
}

const BlindReality<AltPairSpec, alt_reality::AltPair>& alt_reality_for_check() {
  static const AltReality reality;
  return reality;
}

AltSummary summarise_alt_selftest(const std::vector<AltPairResult>& results) {
  return summarise_blind(alt_reality_for_check(), results);
}

std::vector<AltPairResult> run_alt_selftest(const SelftestOptions& options) {
  return run_blind_check(alt_reality_for_check(), options);
}

}  // namespace flange::diagnose
