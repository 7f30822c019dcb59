// SPDX-License-Identifier: MIT
#include "gains_alike_offsets.h"

#include <fmt/format.h>

#include "curve_alike.h"
#include "hats.h"

namespace flange::diagnose {

void judge_gains_alike_offsets(const Parts& parts, Selection& selection) {
  name_classes_alike(parts, selection, &FreeShapeFamily::temperature_alone_also_of,
                     parts.heldout.temp_c,
                     [&](const FreeShapeFit& shape, const HeldoutCurve& heldout) {
                       return curve_of_one_variable_alike(
                                  parts.calibration.temp_c, shape.cal_voltage_v, heldout.x,
                                  heldout.curve, heldout.left, selection.noise_v,
                                  free_shapes::kKnots)
                           .has_value();
                     });
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
