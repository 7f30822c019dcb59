// SPDX-License-Identifier: MIT
#include "blind_check.h"

#include <algorithm>

#include "diagnosis_detail.h"
#include "series_statistics.h"

namespace flange::diagnose {
namespace {

bool holds(const BlindTruth& truth, const std::string& name) {
  return std::find(truth.classes.begin(), truth.classes.end(), name) != truth.classes.end();
}

// Each finding's class and the classes it names as indistinguishable from it.
std::vector<std::vector<std::string>> claimed_sets(const Diagnosis& diagnosis,
                                                   const ClassOfFinding& class_of) {
  std::vector<std::vector<std::string>> sets;
  for (const EffectFinding& f : diagnosis.effects) {
    std::vector<std::string> set{class_of(f)};
    for (const std::string& other : f.indistinguishable_from) {
      EffectFinding alike;
      alike.name = other;
      set.push_back(class_of(alike));
    }
    sets.push_back(std::move(set));
  }
  return sets;
}

void score_among_indistinguishable(const BlindTruth& truth,
                                   const std::vector<std::vector<std::string>>& sets,
                                   BlindScore& score) {
  const auto in_set = [](const std::vector<std::string>& set, const std::string& c) {
    return std::find(set.begin(), set.end(), c) != set.end();
  };
  score.top_among_indistinguishable =
      !sets.empty() && std::any_of(sets.front().begin(), sets.front().end(),
                                   [&](const std::string& c) { return holds(truth, c); });
  score.all_among_indistinguishable =
      std::all_of(truth.classes.begin(), truth.classes.end(), [&](const std::string& c) {
        return std::any_of(sets.begin(), sets.end(),
                           [&](const auto& set) { return in_set(set, c); });
      });
}

void score_in_library(const BlindTruth& truth, const Diagnosis& diagnosis, BlindScore& score) {
  score.verdict_correct = diagnosis.status == Status::kExplained;
  score.top_correct = !score.claimed.empty() && holds(truth, score.claimed.front());
  score.all_found = std::all_of(truth.classes.begin(), truth.classes.end(), [&](const auto& c) {
    return std::find(score.claimed.begin(), score.claimed.end(), c) != score.claimed.end();
  });
  score.nearest_correct = diagnosis.status == Status::kUnexplained && !score.nearest.empty() &&
                          holds(truth, score.nearest);
  score.bias_type = truth.bias_type;
}

void count_in_library(const BlindRow& row, BlindSummary& s, double& shrink_sum,
                      double& excess_sum) {
  const BlindScore& score = row.outcome->score;
  const Status status = row.outcome->diagnosis.status;
  ++s.in_library;
  s.top_correct += score.top_correct ? 1 : 0;
  s.all_found += score.all_found ? 1 : 0;
  s.spurious += score.spurious;
  if (status == Status::kPartlyExplained) {
    ++s.partly_explained_in_library;
    s.partly_top_correct += score.top_correct ? 1 : 0;
  }
  if (status == Status::kUnexplained) {
    ++s.unexplained_in_library;
    s.nearest_correct += score.nearest_correct ? 1 : 0;
  }
  if (score.bias_type) {
    ++s.bias_type;
    shrink_sum += score.shrink_pct;
    excess_sum += score.excess_shrink_pct;
  }
}

void count_outside_library(const BlindRow& row, BlindSummary& s) {
  const BlindScore& score = row.outcome->score;
  const int claimed = score.claimed.empty() ? 0 : 1;
  const int correct = score.verdict_correct ? 1 : 0;
  if (row.truth.kind == BlindKind::kNull) {
    ++s.null_cases;
    s.null_claims += claimed;
    s.null_none += correct;
  } else {
    ++s.outside_cases;
    s.outside_claims += claimed;
    s.outside_unexplained += correct;
  }
}

std::vector<BlindClassRow> class_rows(const std::vector<BlindRow>& rows,
                                      const std::vector<std::string>& class_names) {
  std::vector<BlindClassRow> table;
  for (const std::string& name : class_names) {
    BlindClassRow line;
    line.name = name;
    double excess_sum = 0.0;
    for (const BlindRow& row : rows) {
      if (!in_library(row.truth.kind) || !holds(row.truth, name)) continue;
      const BlindScore& score = row.outcome->score;
      ++line.pairs;
      line.top_correct += score.top_correct ? 1 : 0;
      const auto& named = score.claimed;
      const int is_named = std::find(named.begin(), named.end(), name) != named.end() ? 1 : 0;
      line.named += is_named;
      const bool alone = row.truth.classes.size() == 1;
      (alone ? line.alone : line.shared) += 1;
      (alone ? line.alone_top : line.shared_top) += score.top_correct ? 1 : 0;
      line.shared_named += alone ? 0 : is_named;
      if (score.bias_type) {
        ++line.bias_pairs;
        excess_sum += score.excess_shrink_pct;
      }
    }
    if (line.bias_pairs > 0) line.mean_excess_shrink_pct = excess_sum / line.bias_pairs;
    table.push_back(line);
  }
  return table;
}

std::vector<BlindEffectsRow> effects_rows(const std::vector<BlindRow>& rows) {
  std::vector<BlindEffectsRow> table;
  for (const BlindRow& row : rows) {
    if (!in_library(row.truth.kind)) continue;
    const int effects = static_cast<int>(row.truth.classes.size());
    auto line = std::find_if(table.begin(), table.end(),
                             [&](const BlindEffectsRow& r) { return r.effects == effects; });
    if (line == table.end()) line = table.insert(table.end(), BlindEffectsRow{effects});
    const BlindScore& score = row.outcome->score;
    ++line->cases;
    line->explained += row.outcome->diagnosis.status == Status::kExplained ? 1 : 0;
    line->top_correct += score.top_correct ? 1 : 0;
    line->all_found += score.all_found ? 1 : 0;
    line->top_among_indistinguishable += score.top_among_indistinguishable ? 1 : 0;
    line->all_among_indistinguishable += score.all_among_indistinguishable ? 1 : 0;
    if (score.bias_type) {
      // A running mean, so the row needs no sum kept beside it.
      ++line->bias_cases;
      line->mean_excess_shrink_pct +=
          (score.excess_shrink_pct - line->mean_excess_shrink_pct) / line->bias_cases;
      if (row.outcome->diagnosis.status == Status::kExplained) {
        ++line->explained_bias_cases;
        line->mean_explained_excess_shrink_pct +=
            (score.excess_shrink_pct - line->mean_explained_excess_shrink_pct) /
            line->explained_bias_cases;
      }
    }
  }
  std::sort(table.begin(), table.end(),
            [](const auto& a, const auto& b) { return a.effects < b.effects; });
  return table;
}

}  // namespace

bool in_library(BlindKind kind) { return kind == BlindKind::kSingle || kind == BlindKind::kPair; }

BlindScore score_blind(const BlindTruth& truth, const Diagnosis& diagnosis,
                       const std::vector<EffectFinding>& partial, const ClassOfFinding& class_of) {
  BlindScore score;
  // A partly explained verdict names its effects as found: they are claims too.
  if (diagnosis.status == Status::kExplained || diagnosis.status == Status::kPartlyExplained) {
    for (const EffectFinding& f : diagnosis.effects) score.claimed.push_back(class_of(f));
  }
  if (diagnosis.status == Status::kUnexplained) {
    const EffectFinding* nearest = diagnosis.nearest  ? &*diagnosis.nearest
                                   : !partial.empty() ? &partial.front()
                                                      : nullptr;
    if (nearest != nullptr) {
      score.nearest = class_of(*nearest);
      score.nearest_shrink_pct = nearest->shrink_pct;
    }
  }
  for (const std::string& c : score.claimed) {
    score.claim_right.push_back(holds(truth, c));
    score.spurious += holds(truth, c) ? 0 : 1;
  }
  if (in_library(truth.kind)) {
    score_in_library(truth, diagnosis, score);
    if (!score.claimed.empty()) {
      score_among_indistinguishable(truth, claimed_sets(diagnosis, class_of), score);
    }
  } else {
    score.verdict_correct =
        diagnosis.status == (truth.kind == BlindKind::kNull ? Status::kNone : Status::kUnexplained);
  }
  const double before = diagnosis.heldout_rms_before, after = diagnosis.heldout_rms_after;
  if (before > 0.0) score.shrink_pct = 100.0 * (before - after) / before;
  const double excess_before = rms_above_noise(before, truth.noise_std_v);
  if (excess_before > 0.0) {
    score.excess_shrink_pct =
        100.0 * (1.0 - rms_above_noise(after, truth.noise_std_v) / excess_before);
  }
  return score;
}

BlindSummary summarise_blind(const std::vector<BlindRow>& rows, const BlindAims& aims,
                             const std::vector<std::string>& class_names) {
  BlindSummary s;
  s.cases = static_cast<int>(rows.size());
  double shrink_sum = 0.0, excess_sum = 0.0;
  for (const BlindRow& row : rows) {
    if (in_library(row.truth.kind)) {
      count_in_library(row, s, shrink_sum, excess_sum);
    } else {
      count_outside_library(row, s);
    }
  }
  if (s.bias_type > 0) {
    s.mean_shrink_pct = shrink_sum / s.bias_type;
    s.mean_excess_shrink_pct = excess_sum / s.bias_type;
  }
  s.classes = class_rows(rows, class_names);
  s.by_effects = effects_rows(rows);
  s.top_aim_met = s.in_library == 0 || 100 * s.top_correct >= aims.top_pct * s.in_library;
  s.shrink_aim_met = s.bias_type == 0 || s.mean_excess_shrink_pct >= aims.excess_shrink_pct;
  s.claims_aim_met = s.null_claims == 0 && (!aims.no_claim_outside || s.outside_claims == 0);
  s.none_aim_met =
      aims.none_pct == 0 || s.null_cases == 0 || 100 * s.null_none >= aims.none_pct * s.null_cases;
  return s;
}

DiagnoseOptions blind_diagnose_options(int index, const SelftestOptions& options) {
  DiagnoseOptions diagnose_options;  // blind: the default twin, noise estimated
  diagnose_options.bootstrap_rounds = options.bootstrap_rounds;
  diagnose_options.seed = options.seed + static_cast<std::uint64_t>(index);
  return diagnose_options;
}

void diagnose_blind(const BlindSessions& sessions, int index, const SelftestOptions& options,
                    BlindOutcome& outcome) {
  DiagnosisResult detailed = diagnose_in_detail(sessions.fit, sessions.heldout,
                                                blind_diagnose_options(index, options));
  outcome.diagnosis = std::move(detailed.diagnosis);
  outcome.partial = std::move(detailed.detail.partial);
}

}  // namespace flange::diagnose
