// SPDX-License-Identifier: MIT
// The locomotive scenario: the wheelset's lateral mode from Appendix A, found in the simulated
// response spectrum; the curve's quasi-static shift; wear; brake heating; sampling that picks
// values off the fast dynamics instead of filtering them.
#include "loco_scenario.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "spectrum.h"

namespace flange::sim {
namespace {

using testing::peak_frequency;

// Lateral displacement of a wheelset running over the irregularity on straight track, sampled
// at 1 kHz from the end of the bump (t = 0.5 s at 20 m/s) for `seconds`: its free ringing.
std::vector<double> ringing_after_irregularity(int leads, double seconds) {
  WheelsetLateralParameters parameters;
  parameters.leads = leads;
  WheelsetLateral wheelset(parameters);
  const TrackLayout track;
  const auto force = [&](double t) {
    return -wheelset.mass_kg() * irregularity_acceleration_mps2(track, track.speed_mps * t);
  };
  std::vector<double> ringing;
  const double dt = 1e-3;
  for (int n = 0; n < static_cast<int>((0.5 + seconds) / dt); ++n) {
    wheelset.step(n * dt, dt, force);
    if ((n + 1) * dt > 0.5) ringing.push_back(wheelset.displacement_m());
  }
  return ringing;
}

TEST(WheelsetLateral, LateralModeFromTheResponseSpectrumLiesIn4p5To6p4Hz) {
  for (const int leads : {1, 2}) {
    const std::vector<double> ringing = ringing_after_irregularity(leads, 8.0);
    const double peak_hz = peak_frequency(ringing, 1000.0, 1.0, 20.0, 0.005);
    EXPECT_GE(peak_hz, 4.5) << leads << " lead(s)";
    EXPECT_LE(peak_hz, 6.4) << leads << " lead(s)";
    // And where a damped oscillator with Appendix A's values rings: f_n sqrt(1 - zeta^2).
    WheelsetLateralParameters parameters;
    parameters.leads = leads;
    const double zeta =
        leads * lead_damping_ns_per_m(parameters) / (2.0 * std::sqrt(leads * 2.5e6 * 3105.0));
    EXPECT_NEAR(peak_hz, lateral_natural_frequency_hz(parameters) * std::sqrt(1.0 - zeta * zeta),
                0.05)
        << leads << " lead(s)";
  }
}

TEST(WheelsetLateral, AppendixADampingIsTheThesisLeadDamping) {
  EXPECT_NEAR(lead_damping_ns_per_m(WheelsetLateralParameters{}), 8810.5051, 1e-3);  // d_Lead_y
}

TEST(LocoScenario, TruthAt100HzRingsAtTheLateralModeAfterTheIrregularity) {
  LocoScenario scenario(LocoRun{}, 100.0, 4.0);
  std::vector<double> window;  // 0.5-3.0 s: after the bump, while the curve's ramp is slow
  std::vector<double> times;
  for (std::int64_t n = 0; n < scenario.sample_count(); ++n) {
    const TrueState truth = scenario.next();
    if (truth.t_s >= 0.5 && truth.t_s < 3.0) {
      window.push_back(truth.clearance_mm);
      times.push_back(truth.t_s);
    }
  }
  // Remove the slow trend (curve entry and wear) with a straight-line fit.
  const double count = static_cast<double>(window.size());
  double st = 0, sy = 0, stt = 0, sty = 0;
  for (std::size_t k = 0; k < window.size(); ++k) {
    st += times[k];
    sy += window[k];
    stt += times[k] * times[k];
    sty += times[k] * window[k];
  }
  const double slope = (count * sty - st * sy) / (count * stt - st * st);
  const double intercept = (sy - slope * st) / count;
  for (std::size_t k = 0; k < window.size(); ++k) window[k] -= intercept + slope * times[k];
  const double peak_hz = peak_frequency(window, 100.0, 2.0, 20.0, 0.01);
  EXPECT_GE(peak_hz, 4.5);
  EXPECT_LE(peak_hz, 6.4);
}

TEST(LocoScenario, CurveShiftsTheWheelsetTowardsTheSensorAndTheFlangeWears) {
  const LocoRun run;
  const double duration_s = 63.0;  // three laps of 21 s
  LocoScenario scenario(run, 10.0, duration_s);
  const double shift_mm = run.wheelset.supported_mass_kg * unbalanced_acceleration_mps2(run.track) /
                          (run.wheelset.leads * run.wheelset.lead_stiffness_n_per_m) * 1e3;
  EXPECT_NEAR(shift_mm, 2.56, 0.01);  // 17167 kg x 0.745 m/s^2 on 5e6 N/m
  for (std::int64_t n = 0; n < scenario.sample_count(); ++n) {
    const TrueState truth = scenario.next();
    const double lap_s = std::fmod(truth.t_s, 21.0);
    if (std::abs(lap_s - 10.5) < 1e-9) {  // mid-curve, 200 m into the lap
      const double worn_mm =
          run.initial_clearance_mm + run.wear_over_run_mm * truth.t_s / duration_s;
      EXPECT_NEAR(truth.clearance_mm, worn_mm - shift_mm, 0.02) << truth.t_s;
    }
  }
}

TEST(LocoScenario, BrakeApplicationsHeatTheSensorIntoTheThesisRange) {
  LocoScenario scenario(LocoRun{}, 10.0, 300.0);
  double peak_c = 0.0;
  double before_first_brake_c = 0.0;
  for (std::int64_t n = 0; n < scenario.sample_count(); ++n) {
    const TrueState truth = scenario.next();
    peak_c = std::max(peak_c, truth.temperature_c);
    if (truth.t_s <= 20.0)
      before_first_brake_c = std::max(before_first_brake_c, truth.temperature_c);
  }
  EXPECT_DOUBLE_EQ(before_first_brake_c, 30.0);
  EXPECT_GE(peak_c, 79.0);  // thesis 4.1: 79-98 degC
  EXPECT_LE(peak_c, 98.0);
}

TEST(LocoScenario, SamplingAt6HzPicksValuesOffTheFastDynamicsUnfiltered) {
  // Every 6 Hz instant is also a 300 Hz instant: the slow record holds the same truth, so the
  // lateral ringing survives into it (aliased) instead of being averaged away.
  LocoScenario slow(LocoRun{}, 6.0, 30.0);
  LocoScenario fast(LocoRun{}, 300.0, 30.0);
  double largest_gap_mm = 0.0;
  for (std::int64_t n = 0; n < slow.sample_count(); ++n) {
    const TrueState s = slow.next();
    TrueState f;
    for (int k = 0; k < (n == 0 ? 1 : 50); ++k) f = fast.next();
    ASSERT_DOUBLE_EQ(s.t_s, f.t_s);
    largest_gap_mm = std::max(largest_gap_mm, std::abs(s.clearance_mm - f.clearance_mm));
  }
  EXPECT_LT(largest_gap_mm, 0.01);  // the ringing itself is about +-1 mm
}

}  // namespace
}  // namespace flange::sim
