// SPDX-License-Identifier: MIT
// The alternative bench's reference clearance: three protocols that are none of the twin's
// 0.5 mm zigzag (positions in random order with a smooth move, a motorised sinusoidal sweep, a
// staircase that climbs and snaps back). Closed forms of the session clock.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "alt_random.h"

namespace flange::alt_reality {

enum class MicrometerKind { kRandomPositions, kMotorisedSweep, kSawtoothStaircase };
inline constexpr int kMicrometerKinds = 3;
std::string micrometer_kind_name(MicrometerKind kind);

struct MicrometerProtocol {
  MicrometerKind kind = MicrometerKind::kRandomPositions;
  double low_mm = 1.5, high_mm = 10.0;  // the range used, within the sensor's 1.5-10 mm
  double step_mm = 1.0;                 // staircase: rise per step
  double dwell_s = 20.0;                // random and staircase: time held at a position
  double move_s = 4.0;                  // random and staircase: time to move between positions
  double period_s = 200.0;              // sweep: period
  double phase = 0.0;                   // sweep: phase at t = 0, rad
  std::vector<double> positions_mm;     // random: the positions in order
};

// A protocol of `kind` with parameters drawn for one session of `duration_s`.
MicrometerProtocol draw_micrometer(MicrometerKind kind, double duration_s, AltRandom& random);

// The micrometer reading (the disk's position) at session time `t_s` (the first position
// before 0).
double micrometer_mm(const MicrometerProtocol& protocol, double t_s);

nlohmann::json micrometer_json(const MicrometerProtocol& protocol);

}  // namespace flange::alt_reality
