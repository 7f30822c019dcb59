// SPDX-License-Identifier: MIT
// The threshold stage: thickness, alarm levels, hysteresis, dwell, the wear-step check.
#include "thresholds.h"

#include <gtest/gtest.h>

#include <cmath>

#include "input_error.h"

namespace flange::host {
namespace {

TEST(Thresholds, ThicknessFollowsTheSensorSetting) {
  const ThresholdStage stage(ThresholdConfig{});
  EXPECT_DOUBLE_EQ(stage.flange_mm(2.0), 33.0);
  EXPECT_DOUBLE_EQ(stage.flange_mm(8.0), 27.0);
  EXPECT_DOUBLE_EQ(stage.flange_mm(10.0), 25.0);
}

TEST(Thresholds, WarningNeedsTheDwellAndCriticalLatches) {
  ThresholdStage stage(ThresholdConfig{});
  double t = 0.0;
  auto run = [&](double clearance, double seconds) {
    ThresholdOutput last;
    for (double end = t + seconds; t < end; t += 0.1) last = stage.step(t, clearance);
    return last.level;
  };
  EXPECT_EQ(run(7.0, 10.0), AlarmLevel::kNone);
  EXPECT_EQ(run(8.2, 1.5), AlarmLevel::kNone);  // shorter than the 2 s dwell
  EXPECT_EQ(run(8.2, 1.0), AlarmLevel::kWarning);
  EXPECT_EQ(run(10.3, 3.0), AlarmLevel::kCritical);
  EXPECT_EQ(run(5.0, 10.0), AlarmLevel::kCritical);  // latched
}

TEST(Thresholds, NoiseAroundAThresholdDoesNotChatter) {
  ThresholdConfig config;
  config.hysteresis_mm = 0.1;
  ThresholdStage stage(config);
  int changes = 0;
  // 0.05 mm of alternating noise around 8 mm, for ten minutes at 6 Hz.
  for (int k = 0; k < 3600; ++k) {
    const double clearance = 8.0 + ((k % 2 == 0) ? 0.05 : -0.05);
    if (stage.step(k / 6.0, clearance).level_changed) ++changes;
  }
  EXPECT_LE(changes, 1);
}

TEST(Thresholds, WearStepBetweenWindowsIsReported) {
  ThresholdConfig config;
  config.step_window_s = 10.0;
  config.max_step_mm = 0.5;
  ThresholdStage stage(config);
  int steps = 0;
  double largest = 0.0;
  for (int k = 0; k < 600; ++k) {
    const double t = k * 0.1;
    const double clearance = t < 30.0 ? 4.0 : 5.0;  // a 1 mm jump at 30 s
    const ThresholdOutput out = stage.step(t, clearance);
    if (out.wear_step_mm) {
      ++steps;
      largest = std::max(largest, *out.wear_step_mm);
    }
  }
  EXPECT_EQ(steps, 1);
  EXPECT_NEAR(largest, 1.0, 1e-9);
}

TEST(Thresholds, InvalidConfigurationIsRefused) {
  ThresholdConfig config;
  config.warning_clearance_mm = 11.0;  // beyond the critical clearance of 10 mm
  EXPECT_THROW(ThresholdStage{config}, InputError);
  config = ThresholdConfig{};
  config.min_dwell_s = -1.0;
  EXPECT_THROW(ThresholdStage{config}, InputError);
}

}  // namespace
}  // namespace flange::host
