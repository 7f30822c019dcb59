// SPDX-License-Identifier: MIT
// How each effect class of the class table (classes/effect_classes.h) is fitted: its library
// fitter, its shape-free families and, where a free shape's summary is not the effect's
// parameters, which library member a shape is. The table below the stages says what a class is;
// this one, in the candidates stage, says how the candidates stand for it. A class the diagnosis
// finds by its bias has an entry here (tests/diagnose/class_table_test.cpp checks both tables name
// the same classes).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "effect_catalogue.h"
#include "free_shape_fit.h"

namespace flange::diagnose {

class TwinReplay;
struct EffectFit;

// Fits a bias class on top of the effects modelled (effect_fit.h).
using LibraryFitter = EffectFit (*)(const std::string& name, const TwinReplay& replay,
                                    const std::vector<double>& real_v,
                                    const std::vector<sim::EffectSettings>& modelled);

// The twin's effect that holds a free shape, with its parameters.
struct ShapeMember {
  std::string effect;  // in sim::effect_catalogue()
  sim::ParamValues params;
};

struct ClassFit {
  std::string name;  // a class of effect_classes()
  // The library fit over the class's search ranges (or a class's own closed form).
  LibraryFitter fit = nullptr;
  // The shape-free families that stand for it, in the order they are scored, each with how to
  // make it (candidates/free_shapes/family_makers.h).
  std::vector<FreeShapeFamily> families{};
  // A free shape's library member where its summary's keys are not the effect's parameters (a
  // skew's law: the effect's skew_s is its value at the session's start, the summary's the
  // mid-session one) or the member is another effect of the twin (a lag in volts): the effect
  // and its parameters, or nothing where the shape does what the twin cannot. Unset: the class's
  // own effect with the summary's keys (improved_twin/improved_twin.cpp, library_member).
  std::optional<ShapeMember> (*member_of_shape)(const FreeShapeFit& shape) = nullptr;
};

// The entry of class `name`; a class without one (fitted by nothing: the signature classes and
// the improved twin's table) gets an empty entry.
const ClassFit& class_fit(const std::string& name);

// The class names this table holds, in its order.
std::vector<std::string> classes_with_fits();

// Every free-shape family of every class, in the class table's order.
std::vector<FreeShapeFamily> all_free_shape_families();

}  // namespace flange::diagnose
