// SPDX-License-Identifier: MIT
// What `flange run --manifest` says about each wheel: alarms at a glance and the worst wheel
// (the highest alarm level raised, reached first; without alarms, the largest settled filtered
// clearance).
#include "locomotive_summary.h"

#include <gtest/gtest.h>

#include <vector>

namespace flange::host {
namespace {

// A channel whose run raised `events` and whose settled filtered clearance peaked at max_mm.
ChannelRun channel(int number, const std::vector<AlarmEvent>& events, double max_mm) {
  ChannelRun c;
  c.channel.channel = number;
  c.channel.axle = number / 2 + 1;
  c.channel.side = number % 2 == 0 ? ManifestSide::kLeft : ManifestSide::kRight;
  c.summary.alarm_events = events;
  c.summary.filtered.add(max_mm - 1.0, true);
  c.summary.filtered.add(max_mm, true);
  return c;
}

TEST(LocomotiveSummary, AlarmDigestKeepsTheFirstTimeOfEachLevelAndCountsWearSteps) {
  RunSummary s;
  s.alarm_events = {{10.0, "warning"},          {12.0, "none"},     {20.0, "warning"},
                    {60.0, "wear_step 0.9 mm"}, {70.0, "critical"}, {120.0, "wear_step 0.8 mm"}};
  const AlarmDigest d = digest_alarms(s);
  EXPECT_EQ(d.highest, AlarmLevel::kCritical);
  EXPECT_EQ(d.first_warning_s, 10.0);
  EXPECT_EQ(d.first_critical_s, 70.0);
  EXPECT_EQ(d.wear_steps, 2u);
  EXPECT_EQ(digest_alarms(RunSummary{}).highest, AlarmLevel::kNone);
}

TEST(LocomotiveSummary, TheWorstWheelRaisedTheHighestAlarmFirst) {
  LocomotiveRun run;
  run.channels = {channel(0, {{50.0, "warning"}}, 9.5), channel(1, {{80.0, "critical"}}, 10.2),
                  channel(2, {{40.0, "critical"}}, 10.1), channel(3, {}, 11.0)};
  EXPECT_EQ(worst_channel(run), 2u);  // critical beats warning and no alarm; 40 s beats 80 s
  run.channels = {channel(0, {{50.0, "warning"}}, 8.2), channel(1, {{30.0, "warning"}}, 8.1),
                  channel(2, {}, 9.9)};
  EXPECT_EQ(worst_channel(run), 1u);
}

TEST(LocomotiveSummary, WithoutAlarmsTheLargestFilteredClearanceIsTheWorst) {
  LocomotiveRun run;
  run.channels = {channel(0, {}, 7.1), channel(1, {{100.0, "wear_step 0.6 mm"}}, 7.4),
                  channel(2, {}, 6.0)};
  EXPECT_EQ(worst_channel(run), 1u);
  // A channel with no settled row has no extremes and is not ranked.
  ChannelRun unsettled;
  unsettled.summary.filtered.add(12.0, false);
  run.channels = {unsettled};
  EXPECT_FALSE(worst_channel(run).has_value());
}

}  // namespace
}  // namespace flange::host
