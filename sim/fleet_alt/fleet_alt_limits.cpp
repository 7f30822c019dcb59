// SPDX-License-Identifier: MIT
#include "fleet_alt_limits.h"

namespace flange::fleet_alt {

int last_recorded_day(const LocomotiveHistory& loco) {
  int last = -1;
  for (const LocomotiveDay& day : loco.days) {
    if (day.recorded) last = day.day;
  }
  return last;
}

std::optional<int> limit_day(const FleetAltTruth& truth, int locomotive, int channel, int from,
                             double limit_wear_mm) {
  const LocomotiveHistory& loco = truth.locomotives.at(static_cast<std::size_t>(locomotive));
  const auto c = static_cast<std::size_t>(channel);
  const auto start = static_cast<std::size_t>(from);
  const int axle = channel / 2 + 1, side = channel % 2;
  const double base = loco.positions[c].base_rate.at(start);  // the wheel that ran there
  double wear = loco.days.at(start).wheels[c].wear_mm;
  if (wear >= limit_wear_mm) return from;
  const auto wears_on = [&](int route, double km, double ambient_c) {
    const RouteKind& kind = truth.routes[static_cast<std::size_t>(route)].kind;
    wear += wear_rate_mm_per_1000km(kind, axle, side, base, wear, ambient_c) * km / 1000.0;
    return wear >= limit_wear_mm;  // reached in the day's service
  };
  for (std::size_t d = start; d < loco.days.size(); ++d) {
    if (wears_on(loco.days[d].route, loco.days[d].km, truth.ambient_c[d])) {
      return static_cast<int>(d);
    }
  }
  for (std::size_t k = 0; k < loco.days_after.size(); ++k) {
    const DayAfter& day = loco.days_after[k];
    if (wears_on(day.route, day.km, truth.ambient_after_c.at(k))) {
      return static_cast<int>(loco.days.size() + k);
    }
  }
  return std::nullopt;
}

void date_limits(FleetAltTruth& truth) {
  for (std::size_t l = 0; l < truth.locomotives.size(); ++l) {
    LocomotiveHistory& loco = truth.locomotives[l];
    const int from = last_recorded_day(loco);
    if (from < 0) continue;
    for (int c = 0; c < kWheels; ++c) {
      PositionTruth& position = loco.positions[static_cast<std::size_t>(c)];
      const int l_index = static_cast<int>(l);
      position.warning_day =
          limit_day(truth, l_index, c, from, kWarningClearanceMm - kNewFlangeClearanceMm);
      position.critical_day =
          limit_day(truth, l_index, c, from, kCriticalClearanceMm - kNewFlangeClearanceMm);
    }
  }
}

}  // namespace flange::fleet_alt
