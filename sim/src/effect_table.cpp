// SPDX-License-Identifier: MIT
#include "effect_table.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace flange::sim {
namespace {

// The cell of `knots` that holds x (held at the ends) and x's place in it, 0..1.
std::pair<std::size_t, double> locate(const std::vector<double>& knots, double x) {
  if (x <= knots.front()) return {0, 0.0};
  if (x >= knots.back()) return {knots.size() - 2, 1.0};
  const auto upper = std::upper_bound(knots.begin(), knots.end(), x);
  const auto cell = static_cast<std::size_t>(upper - knots.begin()) - 1;
  return {cell, (x - knots[cell]) / (knots[cell + 1] - knots[cell])};
}

std::string knots_problem(const std::vector<double>& knots, const char* field, bool optional) {
  if (optional && knots.empty()) return "";
  if (knots.size() < 2) return fmt::format("{}: at least 2 knots are needed", field);
  for (std::size_t k = 0; k < knots.size(); ++k) {
    if (!std::isfinite(knots[k])) return fmt::format("{}[{}]: not a finite number", field, k);
    if (k > 0 && knots[k] <= knots[k - 1]) {
      return fmt::format("{}: knots must increase strictly ({}[{}] = {} after {})", field, field, k,
                         knots[k], knots[k - 1]);
    }
  }
  return "";
}

}  // namespace

double EffectTable::added_voltage(double clearance, double temperature, double age) const {
  const auto [i, u] = locate(clearance_mm, clearance);
  const auto [j, w] = locate(temperature_c, temperature);
  double v = (1 - u) * ((1 - w) * added_v[i][j] + w * added_v[i][j + 1]) +
             u * ((1 - w) * added_v[i + 1][j] + w * added_v[i + 1][j + 1]);
  if (!age_days.empty()) {
    const auto [k, a] = locate(age_days, age);
    v += (1 - a) * age_added_v[k] + a * age_added_v[k + 1];
  }
  return v;
}

std::string table_problem(const EffectTable& table) {
  for (const std::string& problem : {knots_problem(table.clearance_mm, "clearance_mm", false),
                                     knots_problem(table.temperature_c, "temperature_c", false),
                                     knots_problem(table.age_days, "age_days", true)}) {
    if (!problem.empty()) return problem;
  }
  if (table.added_v.size() != table.clearance_mm.size()) {
    return fmt::format("added_v: expected {} rows, one per clearance knot",
                       table.clearance_mm.size());
  }
  for (std::size_t i = 0; i < table.added_v.size(); ++i) {
    if (table.added_v[i].size() != table.temperature_c.size()) {
      return fmt::format("added_v[{}]: expected {} values, one per temperature knot", i,
                         table.temperature_c.size());
    }
    for (std::size_t j = 0; j < table.added_v[i].size(); ++j) {
      const double v = table.added_v[i][j];
      if (!std::isfinite(v) || std::abs(v) > 100.0) {
        return fmt::format("added_v[{}][{}] = {} is outside its valid range [-100, 100] V", i, j,
                           v);
      }
    }
  }
  if (table.age_added_v.size() != table.age_days.size()) {
    return fmt::format("age_added_v: expected {} values, one per age knot", table.age_days.size());
  }
  for (std::size_t k = 0; k < table.age_added_v.size(); ++k) {
    const double v = table.age_added_v[k];
    if (!std::isfinite(v) || std::abs(v) > 100.0) {
      return fmt::format("age_added_v[{}] = {} is outside its valid range [-100, 100] V", k, v);
    }
  }
  return "";
}

}  // namespace flange::sim
