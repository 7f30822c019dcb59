// SPDX-License-Identifier: MIT
// The third bench's micrometer, of the kinds both other benches use: a staircase up and back down
// (repeated), positions in random order, a motorised sinusoidal sweep, and a staircase that snaps
// back in one move. Positions are held, and a move between two takes `move_s` along a raised
// cosine; the sweep is a sine between two positions.
#pragma once

#include <nlohmann/json.hpp>
#include <vector>

#include "third_random.h"

namespace flange::third_reality {

enum class MicrometerKind { kUpDownStaircase, kRandomPositions, kSineSweep, kSnapBackStaircase };
inline constexpr int kMicrometerKinds = 4;
const char* micrometer_kind_name(MicrometerKind kind);

struct MicrometerPlan {
  MicrometerKind kind = MicrometerKind::kUpDownStaircase;
  double move_s = 4.0;
  std::vector<double> arrive_s, position_mm;  // held positions: reached at arrive_s (rising)
  double low_mm = 1.5, high_mm = 10.0, period_s = 300.0, phase = 0.0;  // the sweep
  double operator()(double t_s) const;  // the first position before 0
};

// Positions within the sensor's 1.5-10 mm.
MicrometerPlan draw_micrometer_plan(MicrometerKind kind, double duration_s, ThirdRandom& random);

nlohmann::json micrometer_plan_json(const MicrometerPlan& plan);

}  // namespace flange::third_reality
