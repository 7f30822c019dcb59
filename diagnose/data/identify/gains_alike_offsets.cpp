// SPDX-License-Identifier: MIT
#include "gains_alike_offsets.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "calibration_reach.h"
#include "curve_alike.h"
#include "hats.h"

namespace flange::diagnose {

void judge_gains_alike_offsets(const Parts& parts, Selection& selection) {
  for (Pick& pick : selection.picks) {
    if (pick.step.candidates.empty() || !pick.chosen().free_shape) continue;
    const FreeShapeFit& shape = *pick.chosen().free_shape;
    const std::string& other = shape.family.temperature_alone_also_of;
    std::vector<std::string>& alike = pick.finding.indistinguishable_from;
    if (other.empty() || other == pick.finding.name ||
        std::find(alike.begin(), alike.end(), other) != alike.end()) {
      continue;
    }
    // Beyond the calibration's ranges each curve is continued or held as its family does, which
    // no data decide: the two are compared where the held-out part is interpolated.
    std::vector<double> ho_t, ho_curve, ho_left;
    for (const std::size_t i : calibration_reach(parts.calibration, parts.heldout).heldout_within) {
      ho_t.push_back(parts.heldout.temp_c[i]);
      ho_curve.push_back(shape.heldout_voltage_v[i]);
      ho_left.push_back(pick.chosen().heldout_error[i]);
    }
    if (curve_of_one_variable_alike(parts.calibration.temp_c, shape.cal_voltage_v, ho_t, ho_curve,
                                    ho_left, selection.noise_v, free_shapes::kKnots)) {
      alike.push_back(other);
    }
  }
}

std::string tell_gain_from_offset(const EffectFinding& pick, const std::string& other) {
  const auto pivot = pick.params.find("pivot_v");
  const std::string about =
      pivot == pick.params.end() ? "" : fmt::format(" about a pivot at {:.3g} V", pivot->second);
  return fmt::format(
      "to tell {} from {}: the gain{} changes with the recorded voltage by less than the noise "
      "can tell from a curve of the temperature alone; longer sessions that sweep the clearance "
      "over the whole range at each temperature would (a gain scales with the voltage's distance "
      "from its pivot, an offset does not)",
      pick.name, other, about);
}

}  // namespace flange::diagnose
