// SPDX-License-Identifier: MIT
// A table of what an effect adds to the recorded voltage, for an effect known by its values rather
// than by a formula (the `tabulated` effect; docs/sensor_twin.md, "Tabulated effect"): a grid over
// clearance and temperature, interpolated bilinearly, plus an optional curve of the sensor's age,
// interpolated linearly; both are held at their end values beyond their knots.
#pragma once

#include <string>
#include <vector>

namespace flange::sim {

struct EffectTable {
  std::vector<double> clearance_mm;   // >= 2 knots, strictly increasing
  std::vector<double> temperature_c;  // >= 2 knots, strictly increasing
  // added_v[i][j]: what is added at clearance_mm[i] and temperature_c[j], V.
  std::vector<std::vector<double>> added_v;
  // The curve of the sensor's age: empty, or >= 2 knots in days (strictly increasing) with the
  // voltage added at each (age_added_v, same length).
  std::vector<double> age_days;
  std::vector<double> age_added_v;
  bool operator==(const EffectTable&) const = default;

  // What the table adds at this clearance, temperature and age.
  double added_voltage(double clearance_mm, double temperature_c, double age_days) const;
};

// "" when the table is well formed, else one sentence naming the field and what must hold
// ("clearance_mm: knots must increase strictly").
std::string table_problem(const EffectTable& table);

}  // namespace flange::sim
