// SPDX-License-Identifier: MIT
// Sessions that were not recorded: the calibration part's times and one input as recorded, the
// other swept over a chosen span, so that the fits the data leave open can be replayed where they
// would differ (reasons/next_measurement.h).
#pragma once

#include <string>
#include <vector>

#include "recording_series.h"

namespace flange::diagnose {

// What a session sweeps.
struct Sweep {
  std::string variable;       // "temperature" or "clearance"
  std::string unit;           // "degC" or "mm"
  std::vector<double> spans;  // the spans tried, smallest first
};

// The temperature swept over 1 to 80 degC, the clearance over 0.5 to 8 mm (within the bench's
// 1.5-10 mm).
const std::vector<Sweep>& sweeps();

// Where a sweep of `span` runs: about the variable's recorded mean, moved inside the bench's
// operating range (criteria::kOperatingRange*) when it would leave it (a bench heats from room
// temperature and cannot cool below it). {lowest, highest}.
struct SweepRange {
  double lowest = 0.0, highest = 0.0;
};
SweepRange sweep_range(const RecordingSeries& calibration, const std::string& variable,
                       double span);

// `calibration`'s times (at most 8192 of them, evenly spread, so that the sweep's replays stay
// quick) with the swept variable moving once up and back down over its sweep_range, the other
// as recorded, and voltage 0 (a replay needs none).
RecordingSeries hypothetical_session(const RecordingSeries& calibration,
                                     const std::string& variable, double span);

// The bench's whole operating range as one session that was not recorded: `calibration`'s times
// (at most 8192 of them), the temperature once up and back down over
// criteria::kOperatingRangeLowestC-HighestC, and the clearance up and down over
// kOperatingRangeLowestMm-HighestMm twenty times on the way (so that every temperature meets every
// clearance); voltage 0. What a law fitted on the recording is asked to predict outside it.
RecordingSeries operating_range_session(const RecordingSeries& calibration);

}  // namespace flange::diagnose
