// SPDX-License-Identifier: MIT
#include "free_shape_fit.h"

#include <stdexcept>

#include "class_fits.h"
#include "effect_classes.h"
#include "family.h"
#include "series_statistics.h"

namespace flange::diagnose {
namespace {

// The class a shape that is a function of the clearance alone names (the class table's).
const std::string& class_of_a_function_of_clearance_alone() {
  static const std::string name = [] {
    for (const EffectClass& c : effect_classes()) {
      if (c.function_of_clearance_alone) return c.name;
    }
    throw std::logic_error("the class table has no class that is a function of clearance alone");
  }();
  return name;
}

}  // namespace

const std::vector<FreeShapeFamily>& free_shape_families() {
  static const std::vector<FreeShapeFamily> families = all_free_shape_families();
  return families;
}

FreeShapeFit fit_free_shape(const FreeShapeFamily& family, const FreeShapeInputs& in) {
  if (!family.make) {
    throw std::invalid_argument("no way to make the free-shape family '" + family.effect + ", " +
                                family.variable + "'");
  }
  const std::unique_ptr<free_shapes::Family> shape = family.make(in.calibration);
  shape->search(in.calibration, in.cal_gap_v);
  FreeShapeFit fit = shape->fit(in);
  fit.family = family;
  if (shape->shape_is_function_of_clearance_alone() &&
      family.effect != class_of_a_function_of_clearance_alone()) {
    // A curve of V alone over the top: a compression whose knee stays put and a static
    // nonlinearity of V make it alike. Lowering the top is what a compression does, so such a
    // curve keeps the compression's name and names the nonlinearity alike; one that raises the
    // top is named the nonlinearity (identify/fixed_knees.h names the other class either way).
    if (lowers_the_upper_half(in.calibration.replay.nominal_voltage(), fit.cal_voltage_v)) {
      fit.also_of_class = class_of_a_function_of_clearance_alone();
    } else {
      fit.also_of_class = family.effect;
      fit.family.effect = class_of_a_function_of_clearance_alone();
    }
  }
  return fit;
}

}  // namespace flange::diagnose
