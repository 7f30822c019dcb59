// SPDX-License-Identifier: MIT
// The sensor flag kept from one estimate to the next (host/wear/sensor_flag_latch.h): raised
// only when the search still flags the sensor two weeks of data later, held whatever later
// searches say, cleared by a maintenance event on the wheel (not by an odometer reset).
#include "sensor_flag_latch.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "fleet_sensor_flags.h"

namespace flange::host {
namespace {

// Day d of a history, as the wheel's last run at an estimate.
std::string at_day(int d) {
  return d < 10 ? "2026-03-0" + std::to_string(d) + "T06:00:00Z"
                : "2026-03-" + std::to_string(d) + "T06:00:00Z";
}

MaintenanceMark event(int d, const std::string& kind) {
  return {at_day(d), day_of_iso_time(at_day(d)), 0.0, kind};
}

TEST(WearSensorFlagLatch, IsRaisedOnlyWhenTheSearchStillFlagsTheSensorTwoWeeksLater) {
  const std::optional<SensorFlag> first = next_sensor_flag(std::nullopt, true, at_day(1), {});
  ASSERT_TRUE(first.has_value());
  EXPECT_FALSE(first->latched());
  EXPECT_EQ(first->first_flagged, at_day(1));
  // A week later, whatever the search says, it waits.
  EXPECT_EQ(next_sensor_flag(first, false, at_day(8), {}), first);
  EXPECT_EQ(next_sensor_flag(first, true, at_day(14), {}), first);
  // Two weeks of data later: confirmed when still flagged, dropped when not.
  const std::optional<SensorFlag> confirmed = next_sensor_flag(first, true, at_day(15), {});
  ASSERT_TRUE(confirmed.has_value());
  EXPECT_TRUE(confirmed->latched());
  EXPECT_EQ(confirmed->first_flagged, at_day(1));
  EXPECT_EQ(confirmed->confirmed, at_day(15));
  EXPECT_FALSE(next_sensor_flag(first, false, at_day(15), {}).has_value());
  // Never flagged: nothing.
  EXPECT_FALSE(next_sensor_flag(std::nullopt, false, at_day(15), {}).has_value());
  EXPECT_EQ(sensor_flag_text(*first), "flagged since 2026-03-01, not yet confirmed");
  EXPECT_EQ(sensor_flag_text(*confirmed), "flagged since 2026-03-01, confirmed 2026-03-15");
}

TEST(WearSensorFlagLatch, ALatchedFlagHoldsWhenTheSearchNoLongerFlagsTheSensor) {
  const SensorFlag latched{at_day(1), at_day(15)};
  EXPECT_EQ(next_sensor_flag(latched, false, at_day(29), {}), latched);
  // An odometer reset touches no wheel; maintenance before the flag was the depot's before it.
  EXPECT_EQ(next_sensor_flag(latched, false, at_day(29), {event(20, "odometer_reset")}), latched);
  const MaintenanceMark before{"2026-02-20T12:00:00Z", day_of_iso_time("2026-02-20T12:00:00Z"), 0.0,
                               "reprofile"};
  EXPECT_EQ(next_sensor_flag(latched, false, at_day(29), {before}), latched);
}

TEST(WearSensorFlagLatch, AMaintenanceEventOnTheWheelClearsIt) {
  const SensorFlag latched{at_day(1), at_day(15)};
  for (const char* kind : {"sensor_replaced", "reprofile", "wheelset_moved"}) {
    EXPECT_FALSE(next_sensor_flag(latched, false, at_day(29), {event(20, kind)}).has_value())
        << kind;
    // Flagged again after the depot acted: a new flag, to be confirmed anew.
    const auto again = next_sensor_flag(latched, true, at_day(29), {event(20, kind)});
    ASSERT_TRUE(again.has_value()) << kind;
    EXPECT_EQ(again->first_flagged, at_day(29));
    EXPECT_FALSE(again->latched());
  }
  // A pending flag too.
  EXPECT_FALSE(
      next_sensor_flag(SensorFlag{at_day(1), ""}, false, at_day(8), {event(3, "sensor_replaced")})
          .has_value());
}

TEST(WearSensorFlagLatch, AFleetsLatchedWheelIsASensorFaultWithItsDates) {
  FleetWear fleet;
  WheelWear wheel;
  wheel.wheel = {"L01", 2, "right", 3};
  wheel.runs = {{1, at_day(29), day_of_iso_time(at_day(29)), 100.0, 4.0}};
  fleet.wheels = {wheel, wheel};
  fleet.wheels[1].wheel = {"L01", 2, "left", 2};
  WheelHistory history;
  history.wheel = wheel.wheel;
  latch_sensor_flags(fleet, {history}, {{{"L01", 2, "right"}, {at_day(1), at_day(15)}}});
  EXPECT_EQ(fleet.wheels[0].status, "sensor fault");
  ASSERT_TRUE(fleet.wheels[0].sensor_flag.has_value());
  EXPECT_EQ(fleet.wheels[0].sensor_flag->confirmed, at_day(15));
  EXPECT_EQ(fleet.wheels[1].status, "ok");
  EXPECT_FALSE(fleet.wheels[1].sensor_flag.has_value());
}

TEST(WearSensorFlagLatch, AFlagDateThatIsNoTimeIsRefusedNamingIt) {
  try {
    next_sensor_flag(SensorFlag{"2026-13-45", ""}, true, at_day(1), {});
    FAIL() << "a date that is none was taken";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("2026-13-45"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace flange::host
