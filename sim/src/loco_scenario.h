// SPDX-License-Identifier: MIT
// A run of the locomotive past the sensor: the flange wears (days of wear compressed into the
// run), the track's curve shifts the wheelset quasi-statically towards the sensor, its lateral
// irregularity rings the wheelset on its axle-box leads (about 4.5-6.4 Hz), and brake
// applications heat the sensor. The dynamics run at a fine internal step and are sampled at fs,
// so a slow DAQ sees the lateral mode aliased, as the real one would.
#pragma once

#include "brake_heating.h"
#include "scenario.h"
#include "track_layout.h"
#include "wheelset_lateral.h"

namespace flange::sim {

struct LocoRun {
  TrackLayout track;
  WheelsetLateralParameters wheelset;
  BrakeHeating brakes;
  // Static clearance with a part-worn flange (the thesis sets 2 mm on a new 33 mm flange; 4 mm
  // leaves room for the curve to close the gap by ~2.6 mm without touching the sensor range's
  // bottom) growing by wear_over_run_mm, linearly, by the end of the run: service wear of weeks
  // compressed into minutes so that one record crosses the 8 mm warning level (thesis 3.4).
  double initial_clearance_mm = 4.0;
  double wear_over_run_mm = 4.5;
  double internal_step_s = 1e-3;  // integration step limit (1 kHz), far below 1 / 6.4 Hz
};

class LocoScenario final : public Scenario {
 public:
  // fs_hz > 0, duration_s >= 0.
  LocoScenario(const LocoRun& run, double fs_hz, double duration_s);

  std::int64_t sample_count() const override { return sample_count_; }
  TrueState next() override;

  // The wheelset's lateral displacement towards the sensor at the last sample, in mm.
  double lateral_displacement_mm() const { return wheelset_.displacement_m() * 1e3; }

 private:
  // External lateral force on the wheelset at time t: the curve's load minus the irregularity's
  // inertial force.
  double lateral_force_n(double t_s) const;

  LocoRun run_;
  double fs_hz_;
  double duration_s_;
  std::int64_t sample_count_;
  std::int64_t next_sample_ = 0;
  double t_s_ = 0.0;
  double lap_m_;
  WheelsetLateral wheelset_;
  SensorHeating heating_;
};

}  // namespace flange::sim
