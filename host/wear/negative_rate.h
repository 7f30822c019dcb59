// SPDX-License-Identifier: MIT
// A wear rate whose interval lies wholly below zero is no wear: wear only opens the clearance.
// It is either a reprofiling that the depot did not record and the data did not show as a jump
// back (a lathe pass smaller than h, eq. 3.38), or a sensor drifting down. A reprofiling is a
// step, a drift a ramp: the series is fitted once with a step at each run (a new flange from it)
// and once with a drift from each run (linear in days), both with one parameter more than the
// wear line, and the better of the two fits (the smaller residual) names the cause.
#pragma once

#include "wear_line_fit.h"

namespace flange::host {

enum class NegativeRateCause { kMissedReprofiling, kSensorFault };

// A rate whose interval reaches zero while the fleet's wheels wear more than it allows is no wear
// seen (fleet_wear.cpp) only over a history of at least this many days: earlier, a slow flange's
// interval reaches zero because it is still wide. On the second reality's development fleets
// (9201-9255) run weekly, healthy sensors' intervals reached zero beside the fleet's usual wear
// up to seven weeks in; from eight weeks on only drifting sensors' did.
inline constexpr double kNoWearSeenDays = 56.0;

// `series` as the wear line fits it; at least 2 runs either side of a step or onset tried.
// A series too short for either fit is taken for a sensor fault.
NegativeRateCause negative_rate_cause(const WearSeries& series);

// "missed reprofiling" or "sensor fault": the wheel's status.
const char* status_text(NegativeRateCause cause);

}  // namespace flange::host
