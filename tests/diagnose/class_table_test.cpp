// SPDX-License-Identifier: MIT
// The two tables of effect classes name the same classes: the class table below the stages
// (classes/effect_classes.h: what a class is) and the candidates' table above it
// (candidates/class_fits.h: how it is fitted). A class found by its bias needs a fitter (its
// free-shape families, if any, are its own); one found by its signature, or the improved twin's
// table, has neither.
#include "class_fits.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "effect_classes.h"

namespace flange::diagnose {
namespace {

TEST(ClassTables, EveryBiasClassHasAFitter) {
  for (const std::string& name : bias_classes_in_catalogue_order()) {
    const ClassFit& fit = class_fit(name);
    EXPECT_EQ(fit.name, name);
    EXPECT_NE(fit.fit, nullptr) << name;
    for (const FreeShapeFamily& family : fit.families) EXPECT_EQ(family.effect, name);
  }
}

TEST(ClassTables, FitsNameOnlyBiasClassesOfTheClassTable) {
  const std::vector<std::string> bias = bias_classes_in_catalogue_order();
  for (const std::string& name : classes_with_fits()) {
    EXPECT_NE(std::find(bias.begin(), bias.end(), name), bias.end()) << name;
    EXPECT_EQ(effect_class(name).identification, Identification::kByBias) << name;
  }
  EXPECT_EQ(classes_with_fits().size(), bias.size());
}

TEST(ClassTables, SignatureClassesHaveNoFit) {
  for (const EffectClass& c : effect_classes()) {
    if (c.identification != Identification::kBySignature) continue;
    EXPECT_EQ(class_fit(c.name).fit, nullptr) << c.name;
    EXPECT_TRUE(class_fit(c.name).families.empty()) << c.name;
  }
}

// The families are scored class by class in the class table's order.
TEST(ClassTables, FamiliesFollowTheClassTablesOrder) {
  std::vector<std::string> order;
  for (const EffectClass& c : effect_classes()) order.push_back(c.name);
  std::size_t at = 0;
  for (const FreeShapeFamily& family : all_free_shape_families()) {
    const auto index = static_cast<std::size_t>(
        std::find(order.begin(), order.end(), family.effect) - order.begin());
    ASSERT_LT(index, order.size()) << family.effect;
    EXPECT_GE(index, at) << family.effect << " " << family.variable;
    at = index;
  }
  EXPECT_EQ(all_free_shape_families().size(), free_shape_families().size());
}

}  // namespace
}  // namespace flange::diagnose
