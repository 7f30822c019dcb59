// SPDX-License-Identifier: MIT
// The bench scenario follows the thesis's lab protocol: micrometer steps up and down over
// 1.5-10 mm with a dwell at each, the blower heating to about 98 degC and cooling back.
#include "bench_scenario.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace flange::sim {
namespace {

TEST(BenchScenario, MicrometerStepsUpAndDownWithADwellAtEachPosition) {
  const BenchProtocol protocol;
  const double step_s = protocol.move_s + protocol.dwell_s;
  // Dwell values, one per step: 1.5, 2.0, ..., 10.0, 9.5, ..., 1.5, 2.0, ...
  std::vector<double> dwell_positions;
  for (int k = 0; k < 40; ++k) {
    const double mid_dwell_s = k * step_s + protocol.move_s + 0.5 * protocol.dwell_s;
    dwell_positions.push_back(bench_clearance_mm(protocol, mid_dwell_s));
    // Held for the whole dwell.
    EXPECT_EQ(bench_clearance_mm(protocol, k * step_s + protocol.move_s), dwell_positions.back());
    EXPECT_EQ(bench_clearance_mm(protocol, (k + 1) * step_s - 1e-6), dwell_positions.back());
  }
  for (int k = 0; k < 18; ++k) EXPECT_DOUBLE_EQ(dwell_positions[k], 1.5 + 0.5 * k) << k;
  for (int k = 18; k < 35; ++k) EXPECT_DOUBLE_EQ(dwell_positions[k], 10.0 - 0.5 * (k - 17)) << k;
  EXPECT_DOUBLE_EQ(dwell_positions[35], 2.0);
  // Moving between positions is a ramp, not a jump.
  EXPECT_DOUBLE_EQ(bench_clearance_mm(protocol, step_s + 0.5 * protocol.move_s), 1.75);
}

TEST(BenchScenario, BlowerTakesTheSensorToAbout98DegreesAndBack) {
  const BenchProtocol protocol;
  EXPECT_DOUBLE_EQ(bench_temperature_c(protocol, 0.0), 20.0);
  const double peak_c = bench_temperature_c(protocol, protocol.blower_off_s);
  EXPECT_GT(peak_c, 97.0);
  EXPECT_LT(peak_c, 99.0);
  EXPECT_LT(bench_temperature_c(protocol, protocol.duration_s), 21.5);
  // Monotone up while the blower is on, monotone down after.
  for (double t = 10.0; t <= protocol.duration_s; t += 10.0) {
    const bool heating = t <= protocol.blower_off_s;
    EXPECT_EQ(bench_temperature_c(protocol, t) > bench_temperature_c(protocol, t - 10.0), heating)
        << t;
  }
}

TEST(BenchScenario, SamplesAtFsOverTheDuration) {
  BenchScenario scenario(BenchProtocol{}, 6.0, 100.0);
  ASSERT_EQ(scenario.sample_count(), 601);
  TrueState last;
  for (std::int64_t n = 0; n < scenario.sample_count(); ++n) last = scenario.next();
  EXPECT_DOUBLE_EQ(last.t_s, 100.0);
  EXPECT_EQ(sample_count_for(100.0, 0.1), 11);
  EXPECT_EQ(sample_count_for(6.0, 0.1), 1);
}

}  // namespace
}  // namespace flange::sim
