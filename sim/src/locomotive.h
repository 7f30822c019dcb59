// SPDX-License-Identifier: MIT
// The truth at every wheel of a locomotive running the lap, sample by sample. Each axle is one
// wheelset on its axle-box leads (wheelset_lateral.h) and meets the track's curve and lateral
// irregularity later by its distance behind the leading axle at the train's speed; both wheels
// of an axle share its lateral displacement with opposite signs (the wheelset moves towards
// one rail, away from the other). The ambient and the brake heating are shared; each wheel has
// its own part-worn flange (locomotive_wheels.h). The dynamics run at a fine internal step and
// are sampled at fs, so a slow DAQ sees the lateral mode aliased, as the real one would.
#pragma once

#include <cstdint>
#include <vector>

#include "brake_heating.h"
#include "chain_sample.h"
#include "locomotive_wheels.h"
#include "track_layout.h"
#include "wheelset_lateral.h"

namespace flange::sim {

struct LocoRun {
  TrackLayout track;
  WheelsetLateralParameters wheelset;
  // One brake valve applies every axle's brakes at once, and the thesis gives one heating curve
  // for a sensor beside a braked wheel: every wheel's sensor (both bogies alike) follows it.
  BrakeHeating brakes;
  // Static clearance of the nominal (leading left) wheel with a part-worn flange (the thesis
  // sets 2 mm on a new 33 mm flange; 4 mm leaves room for the curve to close the gap by
  // ~2.6 mm without touching the sensor range's bottom) growing by wear_over_run_mm, linearly,
  // by the end of the run: service wear of weeks compressed into minutes so that one record
  // crosses the 8 mm warning level (thesis 3.4).
  double initial_clearance_mm = 4.0;
  double wear_over_run_mm = 4.5;
  WheelSpread spread;  // how the other wheels' flanges differ from the nominal one
  AxleLayout axles;
  double internal_step_s = 1e-3;  // integration step limit (1 kHz), far below 1 / 6.4 Hz
};

class Locomotive {
 public:
  // wheels in 1 .. kMaxWheels (channels 0 .. wheels - 1), fs_hz > 0, duration_s >= 0.
  Locomotive(const LocoRun& run, int wheels, double fs_hz, double duration_s);
  // Wheels 0 .. flanges.size() - 1 (1 to kMaxWheels) with these flanges instead of the spread
  // around run's nominal one: a fleet's wheels, each worn as its own history left it.
  Locomotive(const LocoRun& run, const std::vector<FlangeWear>& flanges, double fs_hz,
             double duration_s);

  int wheels() const { return static_cast<int>(flanges_.size()); }
  std::int64_t sample_count() const { return sample_count_; }

  // Advances to the next sampling instant (call at most sample_count() times) and returns the
  // truth of every wheel there, in channel order.
  const std::vector<TrueState>& next();

  // Flange of wheel `channel` over the run.
  const FlangeWear& flange(int channel) const {
    return flanges_.at(static_cast<std::size_t>(channel));
  }

  // Lateral displacement of axle `axle` (1 to the number of axles in use) towards the left
  // (outer) rail at the last sample, in mm.
  double lateral_displacement_mm(int axle) const;

 private:
  struct Axle {
    double offset_m;  // behind the leading axle
    WheelsetLateral wheelset;
  };

  // External lateral force on `axle`'s wheelset at time t: the curve's load minus the
  // irregularity's inertial force, both where that axle is on the lap.
  double lateral_force_n(const Axle& axle, double t_s) const;
  void integrate_to(double target_t_s);

  LocoRun run_;
  double fs_hz_;
  double duration_s_;
  std::int64_t sample_count_;
  std::int64_t next_sample_ = 0;
  double t_s_ = 0.0;
  double lap_m_;
  std::vector<Axle> axles_;
  SensorHeating heating_;
  std::vector<FlangeWear> flanges_;
  std::vector<TrueState> truth_;
};

}  // namespace flange::sim
