// SPDX-License-Identifier: MIT
// The alternative-reality table's summary: the overall counts against the aims and the
// rows by class.
#include <algorithm>

#include "alt_classes.h"
#include "alt_selftest.h"

namespace flange::diagnose {
namespace {

using alt_reality::AltPairKind;

void count_in_library(const AltPairResult& r, AltSummary& s, double& shrink_sum,
                      double& excess_sum) {
  const AltScore& score = r.score;
  ++s.in_library;
  s.top_correct += score.top_correct ? 1 : 0;
  s.all_found += score.all_found ? 1 : 0;
  s.spurious += score.spurious;
  if (r.diagnosis.status == Status::kPartlyExplained) {
    ++s.partly_explained_in_library;
    s.partly_top_correct += score.top_correct ? 1 : 0;
  }
  if (r.diagnosis.status == Status::kUnexplained) {
    ++s.unexplained_in_library;
    s.nearest_correct += score.nearest_correct ? 1 : 0;
  }
  if (score.bias_type) {
    ++s.bias_type;
    shrink_sum += score.shrink_pct;
    excess_sum += score.excess_shrink_pct;
  }
}

std::vector<AltClassRow> class_rows(const std::vector<AltPairResult>& results) {
  std::vector<AltClassRow> rows;
  for (const alt_reality::AltClass& c : alt_reality::alt_classes()) {
    AltClassRow row;
    row.name = c.name;
    double excess_sum = 0.0;
    for (const AltPairResult& r : results) {
      const auto& truth = r.spec.truth;
      const bool holds = std::any_of(truth.begin(), truth.end(),
                                     [&](const auto& e) { return e.draw.class_name == c.name; });
      if (!holds || r.spec.kind == AltPairKind::kOutside) continue;
      ++row.pairs;
      row.top_correct += r.score.top_correct ? 1 : 0;
      const auto& named = r.score.claimed;
      row.named += std::find(named.begin(), named.end(), c.name) != named.end() ? 1 : 0;
      if (r.score.bias_type) {
        ++row.bias_pairs;
        excess_sum += r.score.excess_shrink_pct;
      }
    }
    if (row.bias_pairs > 0) row.mean_excess_shrink_pct = excess_sum / row.bias_pairs;
    rows.push_back(row);
  }
  return rows;
}

}  // namespace

AltSummary summarise_alt_selftest(const std::vector<AltPairResult>& results) {
  AltSummary s;
  s.pairs = static_cast<int>(results.size());
  double shrink_sum = 0.0, excess_sum = 0.0;
  for (const AltPairResult& r : results) {
    const bool claimed = !r.score.claimed.empty();
    switch (r.spec.kind) {
      case AltPairKind::kSingle:
      case AltPairKind::kDouble:
        count_in_library(r, s, shrink_sum, excess_sum);
        break;
      case AltPairKind::kNull:
        ++s.null_pairs;
        s.null_claims += claimed ? 1 : 0;
        s.null_none += r.diagnosis.status == Status::kNone ? 1 : 0;
        break;
      case AltPairKind::kOutside:
        ++s.outside_pairs;
        s.outside_claims += claimed ? 1 : 0;
        s.outside_unexplained += r.diagnosis.status == Status::kUnexplained ? 1 : 0;
        break;
    }
  }
  if (s.bias_type > 0) {
    s.mean_shrink_pct = shrink_sum / s.bias_type;
    s.mean_excess_shrink_pct = excess_sum / s.bias_type;
  }
  s.classes = class_rows(results);
  s.top_aim_met = s.in_library == 0 || 100 * s.top_correct >= 95 * s.in_library;
  s.shrink_aim_met = s.bias_type == 0 || s.mean_excess_shrink_pct >= 80.0;
  s.claims_aim_met = s.null_claims == 0 && s.outside_claims == 0;
  s.none_aim_met = s.null_pairs == 0 || 100 * s.null_none >= 99 * s.null_pairs;
  return s;
}

}  // namespace flange::diagnose
