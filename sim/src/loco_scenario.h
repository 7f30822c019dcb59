// SPDX-License-Identifier: MIT
// A run of the locomotive past one sensor, the leading left wheel's (the thesis's single
// wheel): the flange wears (days of wear compressed into the run), the track's curve shifts the
// wheelset quasi-statically towards the sensor, its lateral irregularity rings the wheelset on
// its axle-box leads (about 4.5-6.4 Hz), and brake applications heat the sensor. A one-wheel
// Locomotive (locomotive.h) behind the Scenario interface.
#pragma once

#include "locomotive.h"
#include "scenario.h"

namespace flange::sim {

class LocoScenario final : public Scenario {
 public:
  // fs_hz > 0, duration_s >= 0.
  LocoScenario(const LocoRun& run, double fs_hz, double duration_s);

  std::int64_t sample_count() const override { return locomotive_.sample_count(); }
  TrueState next() override { return locomotive_.next().front(); }

  // The wheelset's lateral displacement towards the sensor at the last sample, in mm.
  double lateral_displacement_mm() const { return locomotive_.lateral_displacement_mm(1); }

 private:
  Locomotive locomotive_;
};

}  // namespace flange::sim
