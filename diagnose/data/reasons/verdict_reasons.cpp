// SPDX-License-Identifier: MIT
#include "verdict_reasons.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

#include "criteria.h"
#include "effect_classes.h"

namespace flange::diagnose {

const char* status_text(Status status) {
  switch (status) {
    case Status::kExplained:
      return "explained";
    case Status::kPartlyExplained:
      return "partly explained";
    case Status::kUnexplained:
      return "unexplained";
    case Status::kNone:
      break;
  }
  return "none";
}

std::ostream& operator<<(std::ostream& out, Status status) { return out << status_text(status); }

}  // namespace flange::diagnose

namespace flange::diagnose::reasons {
namespace {

// "within 10 %": the explained criterion as a percentage.
double explained_pct() { return 100.0 * (criteria::kExplainedRatio - 1.0); }

bool follows_age(const EffectFinding& f) { return !effect_class(f.name).age_param.empty(); }

// "what is left is within 10 % of the noise on the N held-out samples within the calibration's
// ranges (...): X V", and "(the held-out part spans ...)": what both reach sentences say.
// "(24.9-69.9 C, 2.46-9.46 mm)": the calibration's ranges.
std::string calibration_ranges(const BeyondReach& b) {
  return fmt::format("({:.1f}-{:.1f} C, {:.2f}-{:.2f} mm)", b.temp_lo_c, b.temp_hi_c,
                     b.clearance_lo_mm, b.clearance_hi_mm);
}
std::string left_within(const BeyondReach& b) {
  return fmt::format(
      "what is left is within {:.0f} % of the noise on the {} held-out samples within the "
      "calibration's ranges {}: {:.4g} V",
      explained_pct(), b.within, calibration_ranges(b), b.left_within_v);
}
std::string heldout_span(const BeyondReach& b) {
  return fmt::format("(the held-out part spans {:.1f}-{:.1f} C, {:.2f}-{:.2f} mm)",
                     b.heldout_temp_lo_c, b.heldout_temp_hi_c, b.heldout_clearance_lo_mm,
                     b.heldout_clearance_hi_mm);
}

}  // namespace

std::string heldout_summary(double before_v, double after_v, double sigma_v) {
  return fmt::format(
      "held-out gap RMS {:.4g} V before, {:.4g} V after the selected effects; white noise {:.4g} V",
      before_v, after_v, sigma_v);
}

std::string missed_in_a_window(double worst_ratio, double from_s, double to_s,
                               double allowed_ratio) {
  return fmt::format(
      "what is left is within {:.0f} % of the noise over the held-out session, but {:.2f} times "
      "the noise from {:.1f} to {:.1f} s (at most {:.2f} times is asked in every {}th of it): "
      "the selected effects miss something there",
      explained_pct(), worst_ratio, from_s, to_s, allowed_ratio, criteria::kLocalWindows);
}

std::string explained() {
  return fmt::format("what is left is within {:.0f} % of the noise", explained_pct());
}

std::string where_the_calibration_reaches(const BeyondReach& b) {
  return "where the calibration reaches " + calibration_ranges(b);
}

std::string explained_within_reach(const BeyondReach& b) {
  return fmt::format(
      "{}; the other {} lie beyond them {}, where the fitted curves are continued past what they "
      "were fitted on: they take {:.0f} % of the gap above the noise there and leave {:.4g} V; a "
      "calibration session that reaches there would tell their shape",
      left_within(b), b.beyond, heldout_span(b), 100.0 * b.beyond_share, b.left_beyond_v);
}

std::string gap_beyond_reach(const BeyondReach& b) {
  return fmt::format(
      "{}; the gap lies on the other {} beyond them {}, {:.4g} V, where the twin's curves are "
      "continued past what they were fitted on; a calibration session that reaches there would "
      "tell their shape",
      left_within(b), b.beyond, heldout_span(b), b.left_beyond_v);
}

std::string none_within_twin_fits(const BeyondReach& b, const std::vector<std::string>& continued) {
  return fmt::format(
      "{}; the other {} lie beyond them {} and beyond the ranges the twin's {} {} fitted on (its "
      "file's fitted_over), where it continues {} past what was measured: {:.4g} V there, which "
      "these data cannot check; a calibration session that reaches there would tell how it goes on",
      left_within(b), b.beyond, heldout_span(b), fmt::join(continued, ", "),
      continued.size() == 1 ? "was" : "were", continued.size() == 1 ? "it" : "them",
      b.left_beyond_v);
}

std::string picks_beyond_twin_fits(const std::vector<EffectFinding>& picks) {
  std::vector<std::string> names;
  for (const EffectFinding& pick : picks) names.push_back(pick.name);
  return fmt::format(
      "{} would change only how the twin continues past those ranges; the data within them ask "
      "for nothing, so {} not a finding",
      fmt::join(names, " and "), names.size() == 1 ? "it is" : "they are");
}

std::string partly_explained(double share, double least_half_share,
                             const std::string& what_is_left) {
  return fmt::format(
      "the selected effects take {:.1f} % of the held-out gap above the noise (at least {:.0f} "
      "% is asked) and {:.1f} % in the half of the session where they take less (at least {:.0f} "
      "%), but {}: the rest is outside the library or of a shape its families miss",
      100.0 * share, 100.0 * criteria::kPartlyExplainedShare, 100.0 * least_half_share,
      100.0 * criteria::kPartlyExplainedShareInEachHalf, what_is_left);
}

std::string what_is_left(double left_v, double allowed_v, double worst_v, double from_s,
                         double to_s, double window_allowed_v) {
  if (left_v > allowed_v) {
    return fmt::format("{:.4g} V is left where the noise allows {:.4g} V", left_v, allowed_v);
  }
  return fmt::format(
      "{:.4g} V is left over the session, within the {:.4g} V the noise allows, but {:.4g} V "
      "from {:.1f} to {:.1f} s, where it allows {:.4g} V",
      left_v, allowed_v, worst_v, from_s, to_s, window_allowed_v);
}

std::string unexplained(bool any_findings) {
  return any_findings ? "the effects that help leave more than the noise: something outside "
                        "the library remains"
                      : "no library effect shrinks the held-out gap significantly";
}

std::string none() {
  return fmt::format(
      "the held-out gap is within {:.0f} % of the twin's noise over the session and in every "
      "window: what an explanation may leave",
      100.0 * (criteria::kExplainedRatio - 1.0));
}

std::string stage_not_confirmed(const std::string& stage) {
  return fmt::format(
      "the calibration part's {} stage exceeds its noise floor, but the held-out part shows no gap "
      "beyond what an explanation may leave: a difference below the noise that the held-out data "
      "do not confirm",
      stage);
}

std::string residue_fit(const std::vector<EffectFinding>& picks, double taken_pct) {
  std::string names, alike;
  for (const EffectFinding& pick : picks) {
    names += (names.empty() ? "" : " and ") + pick.name;
    for (const std::string& other : pick.indistinguishable_from) {
      if (alike.find(other) == std::string::npos) alike += (alike.empty() ? "" : ", ") + other;
    }
  }
  return fmt::format(
      "{} would take {:.0f} % of what stood above the noise on a held-out gap that was no gap, "
      "less than the {:.0f} % a pick must take there{}: a fit of the noise's residue, not a "
      "finding",
      names, taken_pct, 100.0 * criteria::kLeastShareOfNoGapTaken,
      alike.empty() ? "" : ", and no better than " + alike);
}

std::string nearest(bool picked, const EffectFinding& nearest, bool several_picks,
                    const std::string& what_is_left) {
  return fmt::format("{}: it takes the held-out gap RMS from {:.4g} to {:.4g} V ({:.1f} %){}; {}",
                     picked ? "selected, but the effects selected leave too much"
                            : "the nearest candidate, not significant",
                     nearest.heldout_rms_before, nearest.heldout_rms_after, nearest.shrink_pct,
                     picked && several_picks ? " on its own" : "", what_is_left);
}

std::string quantisation_as_noise(double effective_std_v) {
  return fmt::format(
      "the quantisation taken as noise: what is left is compared with the white noise with the "
      "grid's LSB^2/12 in it ({:.4g} V)",
      effective_std_v);
}

std::string converter_grid_modelled(double null_rms_v, double analog_std_v, double lsb_v) {
  return fmt::format(
      "with the converter grid modelled, what is left is compared with {:.4g} V: what quantising "
      "the twin with {:.4g} V of analog noise on the {:.4g} mV grid leaves",
      null_rms_v, analog_std_v, 1e3 * lsb_v);
}

std::string motion_in_the_noise(double verdict_noise_v, double sigma_v) {
  return fmt::format(
      "with the mount motion, the noise what is left is compared with is {:.4g} V (the larger of "
      "the held-out gap's mean squared difference / 2 and the white noise plus the motion's "
      "variance through dV/dd), not the white {:.4g} V",
      verdict_noise_v, sigma_v);
}

std::optional<std::string> clock(const Diagnosis& diagnosis,
                                 const std::vector<EffectFinding>& partial) {
  if (diagnosis.clock == "start times") {
    return fmt::format(
        "the held-out session starts {:.4g} days after the calibration session (the start times "
        "given): effects of the sensor's age are replayed that much older",
        *diagnosis.heldout_starts_after_s / 86400.0);
  }
  const bool weighed =
      std::any_of(diagnosis.effects.begin(), diagnosis.effects.end(), follows_age) ||
      std::any_of(partial.begin(), partial.end(), follows_age) ||
      (diagnosis.nearest && follows_age(*diagnosis.nearest));
  if (diagnosis.clock != "unknown" || !weighed) return std::nullopt;
  return "the held-out clock restarts at 0 and the sessions' start times are unknown: ageing is "
         "a trend within each session, and each session is taken to start at the same age, so a "
         "drift that ran on between the sessions is left as an offset on the held-out part, "
         "unless a free ageing curve placed the held-out session at an age of its own (give "
         "--real-start and --holdout-start)";
}

std::string one_sided_protocol() {
  return "in both sessions each clearance is reached from one side only (the micrometer's last "
         "move before a clearance went the same way at least 95 % of the time there), so the "
         "static nonlinearity cannot be told from a hysteresis, an output that depends on the "
         "direction of the last move (outside the library); a session that reaches each "
         "clearance from both sides would tell them apart";
}

std::string coverage(std::size_t heldout_samples, const RegionCell& cell) {
  return fmt::format(
      "the held-out part has {} samples in the cell where the calibration gap stands out most "
      "({:.2f}-{:.2f} mm x {:.1f}-{:.1f} C, bias {:.4g} V, {} calibration samples): it can neither "
      "confirm nor refute what lies there; a held-out session that reaches that clearance and "
      "temperature would",
      heldout_samples, cell.clearance_lo, cell.clearance_hi, cell.temp_lo, cell.temp_hi,
      cell.bias_v, cell.n);
}

}  // namespace flange::diagnose::reasons
