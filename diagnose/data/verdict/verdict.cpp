// SPDX-License-Identifier: MIT
#include "verdict.h"

#include <algorithm>
#include <numbers>
#include <numeric>
#include <utility>

#include "criteria.h"
#include "effect_classes.h"
#include "reach.h"
#include "regions.h"
#include "series_statistics.h"
#include "series_arithmetic.h"
#include "verdict_reasons.h"

namespace flange::diagnose {
namespace {

// What may be left in any one window of the held-out session: criteria::kLocalExplainedRatio
// times the noise; with the converter's grid modelled, at least LSB / sqrt(2). Below the LSB the
// noise does not spread evenly over the code boundaries: a signal that dwells on a boundary for a
// window flips between two codes at random, half the time off the twin's one code, whatever the
// noise.
double window_allowance(const Signatures& signatures, double verdict_noise) {
  const double allowance = criteria::kLocalExplainedRatio * verdict_noise;
  if (!signatures.quantised_on || signatures.quantisation_as_noise) return allowance;
  return std::max(allowance, signatures.quantised_on->lsb_v / std::numbers::sqrt2);
}

bool left_within_noise_overall(const VerdictFigures& f) {
  return f.rms_after <= criteria::kExplainedRatio * f.noise_v;
}

bool left_within_noise_locally(const VerdictFigures& f) {
  return f.worst_window_v <= f.window_allowance_v;
}

double partly_share(const VerdictFigures& f) {
  return above_noise_share_taken(f.rms_before, f.rms_after, f.noise_v);
}

// The share of the gap above the noise the picks take in the first and in the second half of the
// held-out session, the smaller of the two; a half with no gap above the noise counts 0 (an
// explanation of a gap that lies in one half only is not confirmed over the session).
double least_half_share_taken(const std::vector<double>& before, const std::vector<double>& after,
                              double noise_v) {
  const std::size_t n = after.size();
  double least = 1.0;
  for (const auto& [from, to] : {std::pair<std::size_t, std::size_t>{0, n / 2}, {n / 2, n}}) {
    std::vector<std::size_t> half(to - from);
    std::iota(half.begin(), half.end(), from);
    least = std::min(least, above_noise_share_taken(rms_at(before, half), rms_at(after, half),
                                                    noise_v));
  }
  return least;
}

// The partly explained verdict's reason: the share taken over the session and in its worse half.
std::string partly_explained_reason(const VerdictFigures& f, const std::string& left) {
  return reasons::partly_explained(partly_share(f), f.least_half_share_taken, left);
}

// Picks on a held-out gap that was no gap, none of them found by its signature, taking less than
// criteria::kLeastShareOfNoGapTaken of what little stood above the noise (nothing, from below
// it): nothing in the held-out data asks for them, so they are a fit of the noise's residue.
bool picks_fit_a_residue(const VerdictFigures& f) {
  return f.any_findings && !f.gap_before_picks && !f.found_by_signature &&
         partly_share(f) < criteria::kLeastShareOfNoGapTaken;
}

// Whether the held-out part enters the cell where the calibration gap stands out most with
// enough samples to confirm or refute what lies there.
bool heldout_covers_where(const RecordingSeries& heldout, const Location& detail) {
  if (!detail.where_region) return true;
  return samples_in(heldout, detail.regions[*detail.where_region]).size() >=
         criteria::kLeastSamplesPerCell;
}

// The twin leaves no gap within the calibration's ranges before any pick, and the held-out samples
// beyond them lie beyond the ranges the twin's effects were fitted on (decide(), verdict.h).
bool none_within_twin_fits(const VerdictFigures& f) {
  return f.beyond_past_twin_fits && f.share_within >= criteria::kLeastShareWithinReach &&
         f.within_before_v <= criteria::kExplainedRatio * f.noise_v &&
         f.within_worst_before_v <= f.window_allowance_v;
}

// The replayed effects of the twin that carry the ranges they were fitted on.
std::vector<const sim::EffectSettings*> effects_with_fits(
    const std::vector<sim::EffectSettings>& twin_effects) {
  std::vector<const sim::EffectSettings*> out;
  for (const sim::EffectSettings& effect : twin_effects) {
    if (effect.fitted_over && !each_sessions_own(effect)) out.push_back(&effect);
  }
  return out;
}

// Whether every held-out sample beyond the calibration's ranges lies beyond the ranges one of
// `fitted` was fitted on (and there are some).
bool beyond_past(const RecordingSeries& heldout, const CalibrationReach& reach,
                 const std::vector<const sim::EffectSettings*>& fitted) {
  if (reach.heldout_beyond.empty() || fitted.empty()) return false;
  return std::all_of(reach.heldout_beyond.begin(), reach.heldout_beyond.end(), [&](auto i) {
    return std::any_of(fitted.begin(), fitted.end(), [&](const sim::EffectSettings* e) {
      return !e->fitted_over->contains(heldout.clearance_mm[i], heldout.temp_c[i]);
    });
  });
}

// What is left is above the noise over the session, but within it in every window and on the
// held-out samples within the calibration's ranges (a share of them enough to judge by).
bool left_within_reach(const VerdictFigures& f) {
  return !left_within_noise_overall(f) && left_within_noise_locally(f) &&
         f.share_within >= criteria::kLeastShareWithinReach &&
         f.within_after_v <= criteria::kExplainedRatio * f.noise_v;
}

// What the picks leave against what the noise allows, as a sentence.
std::string what_is_left(const Selection& selection, const Signatures& signatures,
                         double verdict_noise, const HeldoutWindow& worst) {
  return reasons::what_is_left(rms_of(selection.current_error),
                               criteria::kExplainedRatio * verdict_noise, worst.rms_v, worst.from_s,
                               worst.to_s, window_allowance(signatures, verdict_noise));
}

// The library effect an "unexplained" verdict came nearest to: the first it selected, or, when
// none was significant, the candidate that lowered the held-out gap most; with how far it went.
std::optional<EffectFinding> nearest_effect(const Selection& selection,
                                            const Signatures& signatures,
                                            const std::vector<EffectFinding>& findings,
                                            double verdict_noise, const HeldoutWindow& worst) {
  const bool picked = !findings.empty();
  if (!picked && !selection.nearest_unpicked) return std::nullopt;
  EffectFinding nearest = picked ? findings.front() : *selection.nearest_unpicked;
  nearest.evidence = reasons::nearest(picked, nearest, findings.size() > 1,
                                      what_is_left(selection, signatures, verdict_noise, worst));
  return nearest;
}

// The reach's figures, with what `error` leaves within and beyond it.
reasons::BeyondReach beyond_reach(const RecordingSeries& heldout, const CalibrationReach& reach,
                                  const std::vector<double>& error, double beyond_share) {
  const auto [t_lo, t_hi] = std::minmax_element(heldout.temp_c.begin(), heldout.temp_c.end());
  const auto [x_lo, x_hi] =
      std::minmax_element(heldout.clearance_mm.begin(), heldout.clearance_mm.end());
  return {reach.heldout_within.size(),
          reach.heldout_beyond.size(),
          reach.temp_lo_c,
          reach.temp_hi_c,
          reach.clearance_lo_mm,
          reach.clearance_hi_mm,
          *t_lo,
          *t_hi,
          *x_lo,
          *x_hi,
          rms_at(error, reach.heldout_within),
          rms_at(error, reach.heldout_beyond),
          beyond_share};
}

// The verdict's figures, with the held-out figures the report shows filled into `how`.
VerdictFigures verdict_figures(const Parts& parts, const Selection& selection,
                               const Signatures& signatures,
                               const std::vector<EffectFinding>& findings,
                               const Diagnosis& diagnosis, const CalibrationReach& reach,
                               double verdict_noise, const Location& detail,
                               const std::vector<sim::EffectSettings>& twin_effects, HowFar& how) {
  const double sigma = selection.noise_v;
  const bool has_noise_type = std::any_of(findings.begin(), findings.end(), [](const auto& f) {
    return f.noise_type && effect_class(f.name).identification == Identification::kBySignature;
  });
  VerdictFigures f;
  f.any_findings = !findings.empty();
  f.noise_v = verdict_noise;
  f.rms_before = diagnosis.heldout_rms_before;
  f.rms_after = diagnosis.heldout_rms_after;
  how.worst_window = worst_window(parts.heldout, reach, selection.current_error);
  f.window_allowance_v = window_allowance(signatures, verdict_noise);
  // A held-out gap within what an explanation may leave, over the session (against the larger of
  // sigma and the verdict's noise: with a converter or mount motion the twin holds, what the
  // noise leaves is the verdict's noise) and in every window, is no gap: the same gap left after
  // picks would be "explained", so a twin that holds the explanation leaves "none". A stage of
  // the calibration part above its floor makes one only where the held-out part cannot confirm
  // or refute it (it does not enter the cell where the calibration gap lies): otherwise the
  // held-out data decide.
  f.within_worst_before_v = worst_window(parts.heldout, reach, selection.raw_ho_gap).rms_v;
  f.gap_before_picks =
      diagnosis.heldout_rms_before > criteria::kExplainedRatio * std::max(sigma, verdict_noise) ||
      f.within_worst_before_v > f.window_allowance_v ||
      (!diagnosis.stage.empty() && !heldout_covers_where(parts.heldout, detail));
  f.found_by_signature = has_noise_type;
  f.picks_alike = std::any_of(findings.begin(), findings.end(), [](const auto& finding) {
    return !finding.indistinguishable_from.empty();
  });
  f.gap_exists = f.gap_before_picks || has_noise_type || !findings.empty();
  how.within_calibration_samples = reach.heldout_within.size();
  how.within_calibration_rms_before = rms_at(selection.raw_ho_gap, reach.heldout_within);
  how.within_calibration_rms_after = rms_at(selection.current_error, reach.heldout_within);
  f.worst_window_v = how.worst_window.rms_v;
  f.share_within = static_cast<double>(reach.heldout_within.size()) /
                   static_cast<double>(selection.current_error.size());
  f.within_before_v = how.within_calibration_rms_before;
  f.within_after_v = how.within_calibration_rms_after;
  f.least_half_share_taken =
      least_half_share_taken(selection.raw_ho_gap, selection.current_error, verdict_noise);
  f.beyond_share_taken =
      above_noise_share_taken(rms_at(selection.raw_ho_gap, reach.heldout_beyond),
                              rms_at(selection.current_error, reach.heldout_beyond), verdict_noise);
  f.beyond_past_twin_fits = beyond_past(parts.heldout, reach, effects_with_fits(twin_effects));
  return f;
}

}  // namespace

Decision decide(const VerdictFigures& f) {
  if (picks_fit_a_residue(f)) return Decision::kNone;
  const bool overall = left_within_noise_overall(f);
  const bool locally = left_within_noise_locally(f);
  const bool within_reach =
      left_within_reach(f) && f.within_before_v > criteria::kGapRatio * f.noise_v &&
      f.beyond_share_taken >= std::max(criteria::kLeastShareTakenBeyondReach, 1.0 - f.share_within);
  if (f.gap_before_picks && none_within_twin_fits(f)) return Decision::kNoneWithinTwinFits;
  if (f.any_findings && overall && locally) return Decision::kExplained;
  if (f.any_findings && within_reach) return Decision::kExplainedWithinReach;
  if (f.any_findings && partly_share(f) >= criteria::kPartlyExplainedShare &&
      f.least_half_share_taken >= criteria::kPartlyExplainedShareInEachHalf) {
    return Decision::kPartlyExplained;
  }
  return f.gap_exists ? Decision::kUnexplained : Decision::kNone;
}

Status status_of(Decision decision) {
  switch (decision) {
    case Decision::kExplained:
    case Decision::kExplainedWithinReach:
      return Status::kExplained;
    case Decision::kPartlyExplained:
      return Status::kPartlyExplained;
    case Decision::kUnexplained:
      return Status::kUnexplained;
    case Decision::kNone:
    case Decision::kNoneWithinTwinFits:
      break;
  }
  return Status::kNone;
}

VerdictOutcome verdict(const Parts& parts, const Selection& selection,
                       const Signatures& signatures, const VerdictNoise& noise,
                       const std::vector<sim::EffectSettings>& twin_effects, const Location& where,
                       Diagnosis so_far) {
  VerdictOutcome result{std::move(so_far), {}, {}, {}};
  Diagnosis& diagnosis = result.diagnosis;
  const std::vector<EffectFinding> findings = findings_of(selection, signatures);
  diagnosis.heldout_rms_before = rms_of(selection.raw_ho_gap);
  diagnosis.heldout_rms_after = rms_of(selection.current_error);
  const CalibrationReach reach = calibration_reach(parts.calibration, parts.heldout);
  HowFar& how = result.how_far;
  const VerdictFigures f = verdict_figures(parts, selection, signatures, findings, diagnosis, reach,
                                           noise.rms_v, where, twin_effects, how);
  const Decision decision = decide(f);
  diagnosis.status = status_of(decision);
  auto& reasons = result.reasons;
  reasons.push_back(reasons::heldout_summary(f.rms_before, f.rms_after, selection.noise_v));
  if (!noise.why.empty()) reasons.push_back(noise.why);
  if (f.any_findings && left_within_noise_overall(f) && !left_within_noise_locally(f)) {
    reasons.push_back(reasons::missed_in_a_window(f.worst_window_v / f.noise_v,
                                                  how.worst_window.from_s, how.worst_window.to_s,
                                                  f.window_allowance_v / f.noise_v));
  }
  // The reach's figures with what the picks leave: the scope and the reach sentences.
  const reasons::BeyondReach left =
      beyond_reach(parts.heldout, reach, selection.current_error, f.beyond_share_taken);
  if (decision == Decision::kExplainedWithinReach || decision == Decision::kNoneWithinTwinFits) {
    diagnosis.scope = reasons::where_the_calibration_reaches(left);
  }
  switch (decision) {
    case Decision::kExplained:
      reasons.push_back(reasons::explained());
      break;
    case Decision::kExplainedWithinReach:
      reasons.push_back(reasons::explained_within_reach(left));
      break;
    case Decision::kPartlyExplained:
      reasons.push_back(partly_explained_reason(
          f, what_is_left(selection, signatures, noise.rms_v, how.worst_window)));
      break;
    case Decision::kUnexplained:
      result.partial = findings;
      diagnosis.nearest =
          nearest_effect(selection, signatures, findings, noise.rms_v, how.worst_window);
      reasons.push_back(reasons::unexplained(f.any_findings));
      if (left_within_reach(f)) {
        reasons.push_back(reasons::gap_beyond_reach(left));
      }
      break;
    case Decision::kNone:
      reasons.push_back(reasons::none());
      if (!diagnosis.stage.empty()) {
        reasons.push_back(reasons::stage_not_confirmed(diagnosis.stage));
      }
      if (picks_fit_a_residue(f)) {
        reasons.push_back(reasons::residue_fit(findings, 100.0 * partly_share(f)));
      }
      break;
    case Decision::kNoneWithinTwinFits: {
      std::vector<std::string> continued;
      for (const sim::EffectSettings* e : effects_with_fits(twin_effects)) {
        continued.push_back(e->name);
      }
      reasons.push_back(reasons::none_within_twin_fits(
          beyond_reach(parts.heldout, reach, selection.raw_ho_gap, f.beyond_share_taken),
          continued));
      if (f.any_findings) reasons.push_back(reasons::picks_beyond_twin_fits(findings));
      break;
    }
  }
  if (decision == Decision::kExplained || decision == Decision::kExplainedWithinReach ||
      decision == Decision::kPartlyExplained) {
    diagnosis.effects = findings;
  }
  if (diagnosis.status != Status::kNone) {
    reasons.insert(reasons.end(), selection.confounded.begin(), selection.confounded.end());
    reasons.insert(reasons.end(), selection.dropped.begin(), selection.dropped.end());
  }
  if (diagnosis.stage.empty()) diagnosis.stage = "none";
  return result;
}

}  // namespace flange::diagnose
