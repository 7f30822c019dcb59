// SPDX-License-Identifier: MIT
// A synthetic fleet whose wear per km is r exp(b wear) (wear_acceleration.h), with each wheel's
// true km from its last run to the warning clearance: the fleet the acceleration's tests and the
// plan's estimate.
#pragma once

#include <cstdint>
#include <vector>

#include "fleet_wear.h"

namespace flange::testing {

struct SyntheticFleet {
  std::vector<host::WheelHistory> histories;
  // Each wheel's true km from its last run to the warning clearance, by its position (its
  // locomotive's number less one times 12, plus its channel).
  std::vector<double> true_km_to_warning;
};

// Five locomotives of six axles over 120 days: depot days every 6th, 150-750 km on the others,
// 0.01 mm of noise per run; each wheel its own rate at no wear (0.03-0.12 mm per 1000 km) times
// exp(b wear), starting at 0.5-4.4 mm of wear; an axle whose worse flange passes 4.6 mm is turned
// back to 0.05 mm (recorded). The clearance is 2 mm (a new flange's) plus the wear.
SyntheticFleet synthetic_accelerating_fleet(double b, std::uint32_t seed);

}  // namespace flange::testing
