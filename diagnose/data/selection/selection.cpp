// SPDX-License-Identifier: MIT
#include "selection.h"

#include <algorithm>
#include <cmath>

#include "series_arithmetic.h"
#include "series_statistics.h"

namespace flange::diagnose {

std::vector<EffectFinding> findings_of(const Selection& selection) {
  std::vector<EffectFinding> findings;
  for (const Pick& pick : selection.picks) findings.push_back(pick.finding);
  if (selection.quantisation) {
    // Each pick takes sqrt(before^2 - after^2) of the held-out gap's RMS; the converter's size is
    // what its rounding puts in the gap, which the grid itself shows whether or not the twin's
    // converter reproduces the codes.
    const double rounding_rms = selection.quantised_on->lsb_v / std::sqrt(12.0);
    const auto smaller =
        std::find_if(findings.begin(), findings.end(), [&](const EffectFinding& f) {
          return rms_above_noise(f.heldout_rms_before, f.heldout_rms_after) < rounding_rms;
        });
    findings.insert(smaller, *selection.quantisation);
  }
  if (selection.vibration) findings.push_back(*selection.vibration);
  return findings;
}

std::vector<double> cal_target(const Parts& parts, const Selection& selection) {
  return minus(parts.calibration.voltage_v, selection.cal_free_v);
}

std::vector<double> ho_target(const Parts& parts, const Selection& selection) {
  return minus(parts.heldout.voltage_v, selection.ho_free_v);
}

bool class_taken(const std::string& name, const Selection& selection) {
  return std::any_of(selection.modelled.begin(), selection.modelled.end(),
                     [&](const auto& m) { return m.name == name; }) ||
         std::any_of(selection.picks.begin(), selection.picks.end(),
                     [&](const Pick& p) { return p.finding.name == name; });
}

void add_free_shape(Selection& selection, const FreeShapeFit& shape, double sign) {
  for (std::size_t i = 0; i < selection.cal_free_v.size(); ++i) {
    selection.cal_free_v[i] += sign * shape.cal_voltage_v[i];
  }
  for (std::size_t i = 0; i < selection.ho_free_v.size(); ++i) {
    selection.ho_free_v[i] += sign * shape.heldout_voltage_v[i];
  }
}

void erase_library_effect(Selection& selection, int index) {
  selection.modelled.erase(selection.modelled.begin() + index);
  for (Pick& pick : selection.picks) pick.modelled_index -= pick.modelled_index > index ? 1 : 0;
}

void refresh_library_params(Selection& selection) {
  for (Pick& pick : selection.picks) {
    if (pick.modelled_index >= 0) {
      pick.finding.params = selection.modelled[static_cast<std::size_t>(pick.modelled_index)].params;
    }
  }
}

}  // namespace flange::diagnose
