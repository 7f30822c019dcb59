// SPDX-License-Identifier: MIT
// The diagnosis as a pipeline of stages, in the order they run (docs/diagnose.md, "Stages"):
// input, replay, noise, locate, selection (candidates scored on held-out data), the noise-type
// signatures, the verdict and its reasons.
#include <algorithm>
#include <cmath>
#include <optional>

#include "alarm_timing.h"
#include "alike_classes.h"
#include "backward.h"
#include "confidence.h"
#include "criteria.h"
#include "degenerate_data.h"
#include "diagnosis_detail.h"
#include "effect_classes.h"
#include "final_fit.h"
#include "how_far.h"
#include "improved_twin.h"
#include "inclusion.h"
#include "locate.h"
#include "next_measurement.h"
#include "null_replica_twin.h"
#include "parameter_resolution.h"
#include "parts.h"
#include "protocol.h"
#include "quantisation.h"
#include "sample_rate.h"
#include "selection.h"
#include "session_clock.h"
#include "session_lines.h"
#include "stage_gaps.h"
#include "start.h"
#include "twin_noise.h"
#include "two_passes.h"
#include "verdict.h"
#include "verdict_reasons.h"
#include "vibration.h"

namespace flange::diagnose {
namespace {

// The sentences on what the sessions' clocks, their protocol and the held-out part's coverage
// of the where-cell let the data tell, where they bear on the verdict.
void add_context_reasons(const Parts& parts, DiagnosisResult& result) {
  const Diagnosis& diagnosis = result.diagnosis;
  std::vector<std::string>& reasons = result.detail.reasons;
  if (auto why = reasons::clock(diagnosis, result.detail.partial)) reasons.push_back(*why);
  reasons.insert(reasons.end(), diagnosis.degenerate.begin(), diagnosis.degenerate.end());
  const bool static_in_clearance =
      std::any_of(diagnosis.effects.begin(), diagnosis.effects.end(),
                  [](const auto& f) { return effect_class(f.name).function_of_clearance_alone; });
  if (static_in_clearance && last_move_set_by_clearance(parts.calibration) &&
      last_move_set_by_clearance(parts.heldout)) {
    reasons.push_back(reasons::one_sided_protocol());
  }
}

// When the held-out part barely enters the cell where the calibration gap stands out most, it can
// neither confirm nor refute what lies there: the reason says so, and which data would.
void add_coverage_reason(DiagnosisResult& result) {
  const DiagnosisDetail& detail = result.detail;
  if (result.diagnosis.status == Status::kNone || !detail.where_region ||
      detail.how_far.region_samples >= criteria::kLeastSamplesPerCell) {
    return;
  }
  result.detail.reasons.push_back(
      reasons::coverage(detail.how_far.region_samples, detail.regions[*detail.where_region]));
}

// A gap without noise, or of a constant voltage, has no band or change points to find: the PSD of
// a constant leaks from its 0 Hz bin and binary segmentation splits rounding.
void forget_structure(Location& detail) {
  detail.band_hz.reset();
  detail.segments.clear();
}

// The noise stage's value, or the white noise the selection re-estimated on what its picks leave
// (Selection::reestimated_noise), which the diagnosis then reports.
TwinNoise noise_after_selection(const TwinNoise& stage, const Selection& selection) {
  if (!selection.reestimated_noise) return stage;
  TwinNoise after = stage;
  after.white_noise = *selection.reestimated_noise;
  after.noise_std_v = selection.noise_v;
  after.noise_source = selection.reestimated_noise->source;
  return after;
}

// Mount motion is each session's own random motion: a twin that holds it is replayed without it
// (a replayed realisation would add to the gap, not take from it); its signature is recognised as
// always, goes into the noise the verdict compares with, and is not a finding again.
DiagnoseOptions without_mount_motion(const DiagnoseOptions& given) {
  DiagnoseOptions replayed = given;
  std::erase_if(replayed.twin.effects,
                [](const sim::EffectSettings& e) { return effect_class(e.name).is_mount_motion; });
  return replayed;
}

// A twin holding lines of each session (the mains) is diagnosed on the recordings less each
// part's own lines, without them; the improved twin holds them again.
DiagnosisResult diagnose_without_session_lines(const SessionLines& lines,
                                               const DiagnoseOptions& given) {
  DiagnosisResult result = diagnose_in_detail(lines.calibration, lines.heldout, lines.options);
  result.detail.reasons.push_back(lines.reason);
  std::vector<sim::EffectSettings>& effects = result.improved_twin.twin.effects;
  for (const sim::EffectSettings& effect : given.twin.effects) {
    const bool held =
        std::any_of(effects.begin(), effects.end(),
                    [&](const sim::EffectSettings& e) { return e.name == effect.name; });
    if (!held) effects.push_back(effect);
  }
  return result;
}

}  // namespace

DiagnosisResult diagnose_in_detail(const RecordingSeries& calibration,
                                   const RecordingSeries& heldout, const DiagnoseOptions& given) {
  const DiagnoseOptions options = without_mount_motion(given);
  const bool twin_holds_motion = options.twin.effects.size() < given.twin.effects.size();
  // Input: the parts' shared rate and how their clocks relate.
  const double fs_hz = shared_sample_rate_hz(calibration, heldout);
  sim::check_twin_config(options.twin);
  const SessionClock clock = session_clock(calibration, heldout);
  if (const std::optional<SessionLines> lines = take_out_session_lines(
          calibration, heldout, given, clock.age_offset_s, clock.heldout_age_unknown())) {
    return diagnose_without_session_lines(*lines, given);
  }
  Diagnosis so_far;
  so_far.clock = clock.kind;
  if (!clock.heldout_age_unknown()) so_far.heldout_starts_after_s = clock.age_offset_s;
  // Replay: the twin as given on both parts, and the converter grid they share.
  const Parts parts =
      replay_parts(calibration, heldout, options, clock.age_offset_s, clock.heldout_age_unknown());
  const std::vector<double> cal_base = parts.cal_replay.voltage(options.twin.effects);
  // Noise and locate: the white noise, and where the gap lies on the calibration part.
  const TwinNoise noise = estimate_noise(calibration, cal_base, options);
  const double noise_v = std::max(noise.noise_std_v, 1e-9);
  so_far.noise_std_v = noise_v;
  const DegenerateData degenerate = degenerate_data(calibration, noise.noise_std_v);
  so_far.degenerate = degenerate.sentences;
  Location where = locate(calibration, cal_base, fs_hz, options, noise,
                          null_replica(parts.cal_replay, given, noise.white_noise));
  if (degenerate.nothing_to_locate()) forget_structure(where);
  const std::vector<double> ho_base = parts.ho_replay.voltage(options.twin.effects);
  where.stages = confirm_alarm_timing_on_heldout(
      heldout, ho_base, options, noise.white_noise, fs_hz, std::move(where.stages),
      null_replica(parts.ho_replay, given, noise.white_noise));
  so_far.stage = first_significant_stage(where.stages);
  // Selection: candidates scored on held-out data, forward, refined, backward.
  Selection selection = select_in_two_passes(
      parts, options, noise.adc_grid,
      starting_selection(parts, options.twin.effects, cal_base, ho_base, noise_v));
  measure_inclusion(parts, selection);
  drop_unneeded_picks(parts, selection);
  measure_picks_in_final_fit(parts, selection);
  selection = resolve_parameters(parts, std::move(selection));
  judge_alike_classes(parts, selection);
  const TwinNoise reported_noise = noise_after_selection(noise, selection);
  if (selection.reestimated_noise) so_far.noise_std_v = selection.noise_v;
  // Signatures: the noise-type classes; a converter that reproduces the codes joins the model.
  QuantisationSignature converter = recognise_quantisation(
      parts, reported_noise.white_noise, options.twin.noise.rounding_lsb_v, selection);
  if (converter.replay) selection = with_converter_replayed(std::move(selection), *converter.replay);
  MotionSignature motion = recognise_vibration(parts, selection);
  const Signatures signatures{std::move(converter.finding), std::move(converter.grid),
                              converter.as_noise,
                              twin_holds_motion ? std::nullopt : std::move(motion.finding)};
  const VerdictNoise verdict_noise =
      with_converter_grid(signatures, reported_noise.white_noise, std::move(motion.noise));
  // Verdict and reasons, assembled with the stages' values.
  VerdictOutcome outcome = verdict(parts, selection, signatures, verdict_noise,
                                   options.twin.effects, where, std::move(so_far));
  DiagnosisResult result;
  result.diagnosis = std::move(outcome.diagnosis);
  static_cast<TwinNoise&>(result.detail) = reported_noise;
  static_cast<Location&>(result.detail) = std::move(where);
  result.detail.partial = std::move(outcome.partial);
  result.detail.reasons = std::move(outcome.reasons);
  add_context_reasons(parts, result);
  result.detail.how_far =
      measure_how_far(heldout, selection, result.detail, std::move(outcome.how_far));
  result.detail.heldout_t_s = heldout.t_s;
  result.detail.heldout_gap_before_v = selection.raw_ho_gap;
  result.detail.heldout_gap_after_v = selection.current_error;
  add_coverage_reason(result);
  // What would tell the picks apart or determine them; a "none" names no finding to ask about.
  if (result.diagnosis.status != Status::kNone) {
    result.diagnosis.next_measurement = next_measurements(parts, selection);
  }
  result.diagnosis.effects = with_confidences(result.diagnosis.effects, result.diagnosis.status);
  // The improved twin: the one given, with what the diagnosis found.
  result.improved_twin = improved_twin(parts, selection, signatures, result.diagnosis,
                                       reported_noise.white_noise, given.twin);
  return result;
}

Diagnosis diagnose(const RecordingSeries& calibration, const RecordingSeries& heldout,
                   const DiagnoseOptions& options) {
  return diagnose_in_detail(calibration, heldout, options).diagnosis;
}

}  // namespace flange::diagnose
