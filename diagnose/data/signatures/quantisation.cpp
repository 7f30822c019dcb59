// SPDX-License-Identifier: MIT
#include "quantisation.h"

#include <algorithm>
#include <cmath>

#include "criteria.h"
#include "effect_classes.h"
#include "evidence.h"
#include "quantised_noise.h"
#include "series_statistics.h"
#include "series_arithmetic.h"

namespace flange::diagnose {
namespace {

EffectFinding grid_finding(const AdcGrid& grid) {
  EffectFinding finding;
  finding.name = converter_class();
  finding.params = grid.as_effect().params;
  finding.params["lsb_v"] = grid.lsb_v;
  finding.noise_type = true;
  finding.inclusion = 1.0;
  finding.evidence = evidence::converter_grid(grid);
  return finding;
}

// With the boundaries placed first: their threshold on the converter and in the finding, the held
// out gap before them as its "before", and the sentences that say so.
void add_placement(const Selection& selection, sim::EffectSettings& converter,
                   EffectFinding& finding) {
  const ConverterPlacement& placed = *selection.converter;
  converter.params["threshold_lsb"] = placed.threshold_lsb;
  finding.params["threshold_lsb"] = placed.threshold_lsb;
  finding.heldout_rms_before = rms_of(selection.raw_ho_gap);
  finding.evidence +=
      evidence::converter_boundaries(placed.threshold_lsb, placed.offset_v,
                                     rms_of(selection.raw_ho_gap), rms_of(selection.ho_gap));
  if (placed.gain) {
    finding.params["calibration_gain"] = *placed.gain;
    finding.params["calibration_offset_v"] = placed.gain_offset_v;
    finding.evidence += evidence::daq_gain(*placed.gain, placed.gain_offset_v);
  }
}

}  // namespace

void recognise_quantisation(const Parts& parts, const WhiteNoise& white,
                            double held_rounding_lsb_v, Selection& selection) {
  if (!parts.grid) return;
  const AdcGrid& grid = *parts.grid;
  // A twin that holds a converter replays its codes already: the grid sets the noise the verdict
  // compares with, and is not a finding again.
  if (std::any_of(selection.modelled.begin(), selection.modelled.end(),
                  [](const sim::EffectSettings& e) { return effect_class(e.name).is_converter; })) {
    selection.quantised_on = grid;
    return;
  }
  // A twin whose noise holds this grid's rounding (its codes were not reproduced): the same.
  if (std::abs(held_rounding_lsb_v - grid.lsb_v) <= criteria::kSameGridShare * grid.lsb_v) {
    selection.quantised_on = grid;
    selection.quantisation_as_noise = true;
    return;
  }
  EffectFinding finding = grid_finding(grid);
  sim::EffectSettings converter = grid.as_effect();
  finding.heldout_rms_before = rms_of(selection.current_error);
  // With the boundaries placed first, their offset is in the targets; the converter replayed
  // here carries it instead, so it comes out of them.
  std::vector<double> target = ho_target(parts, selection);
  const double offset_v = selection.converter ? selection.converter->offset_v : 0.0;
  if (selection.converter) {
    add_placement(selection, converter, finding);
    for (double& v : target) v += offset_v;
  }
  std::vector<sim::EffectSettings> with = selection.modelled;
  with.push_back(converter);
  std::vector<double> replayed = minus(target, parts.ho_replay.voltage(with));
  const double null_rms = quantised_null_rms(white.analog_std_v, grid.lsb_v);
  if (rms_of(replayed) <= criteria::kExplainedRatio * null_rms) {
    selection.current_error = std::move(replayed);
    selection.modelled = with;
    for (double& v : selection.cal_free_v) v -= offset_v;
    for (double& v : selection.ho_free_v) v -= offset_v;
  } else {
    selection.quantisation_as_noise = true;
    finding.evidence += evidence::quantisation_as_noise(rms_of(replayed), null_rms, grid.lsb_v);
  }
  finding.heldout_rms_after =
      selection.converter ? rms_of(selection.ho_gap) : rms_of(selection.current_error);
  finding.shrink_pct = 100.0 * (finding.heldout_rms_before - finding.heldout_rms_after) /
                       std::max(finding.heldout_rms_before, 1e-30);
  selection.quantisation = finding;
  selection.quantised_on = grid;
}

}  // namespace flange::diagnose
