// SPDX-License-Identifier: MIT
// The truth's limit dates: the day each wheel position's flange reaches the warning and the
// critical limit. The flange is the one that ran there on its locomotive's last recorded day (the
// one an estimate from the recordings extends); from that day's start it wears on by the wear law
// of fleet_alt_plan.h (route, axle, season and the faster wear of a thinner flange) over the km
// its locomotive runs: the rest of the period as it was run, then the days after it
// (LocomotiveHistory::days_after), with no lathe pass, wheelset move or sensor change. The date
// is the day in whose service the wear reaches the limit; none when that is past
// kTruthHorizonDays.
//
// The limits are wear: a clearance limit less the sensor's setting over a new flange
// (kNewFlangeClearanceMm), as the service path's defaults state them: a warning at 8 mm of
// clearance and a critical alarm at a 25 mm flange of a 33 mm new one (10 mm of clearance).
#pragma once

#include <optional>

#include "fleet_alt_plan.h"

namespace flange::fleet_alt {

inline constexpr double kWarningClearanceMm = 8.0;
inline constexpr double kCriticalClearanceMm = 33.0 + kNewFlangeClearanceMm - 25.0;

// The last day (from day 0) on which the locomotive's recorder kept a recording; -1 if none.
int last_recorded_day(const LocomotiveHistory& loco);

// The day (from day 0) on which the flange of position `channel` reaches `limit_wear_mm`, worn on
// from the start of day `from` as above; nothing within kTruthHorizonDays.
std::optional<int> limit_day(const FleetAltTruth& truth, int locomotive, int channel, int from,
                             double limit_wear_mm);

// Sets every position's warning_day and critical_day (from its locomotive's last recorded day).
void date_limits(FleetAltTruth& truth);

}  // namespace flange::fleet_alt
