// SPDX-License-Identifier: MIT
// A depot's fleet over days: the truth the fleet scenario simulates and `flange wear` must find.
// Each locomotive runs on most days (its own distance each day) and stands in the depot on the
// others; each wheel's flange wears at its own rate per km; the depot reprofiles a wheelset
// (both wheels of an axle: one pass of the wheel lathe) on a depot day once its more worn wheel
// has passed the depot's own limit; one or two sensors drift (their output offset creeps by
// days, whatever the distance). Everything is drawn from one seed; docs/fleet.md gives the
// draws and their ranges.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace flange::sim {

struct FleetSettings {
  int locomotives = 3;     // 1 to kMaxFleetLocomotives
  int days = 90;           // 1 to kMaxFleetDays
  std::uint64_t seed = 0;  // every draw below comes from it
  int start_day = 20454;   // day 0's date, in days since 1970-01-01 (2026-01-01)
};

inline constexpr int kMaxFleetLocomotives = 100;
inline constexpr int kMaxFleetDays = 3650;

// How the fleet's truth is drawn. A wheel's wear per 1000 km is uniform in the side's range:
// the outer (left) flange runs against the rail in the lap's right-hand curve and wears faster.
struct FleetDraws {
  double depot_day_chance = 0.15;  // a locomotive stands in the depot (runs no km) that day
  double min_day_km = 150.0;       // a running day's distance, uniform in [min, max]
  double max_day_km = 750.0;
  double left_rate_low = 0.05, left_rate_high = 0.10;     // mm per 1000 km, outer wheel
  double right_rate_low = 0.025, right_rate_high = 0.06;  // mm per 1000 km, inner wheel
  double initial_wear_low_mm = 0.3;                       // wear at day 0 (part-worn), uniform
  double initial_wear_high_mm = 4.0;
  // The depot reprofiles an axle on a depot day when its more worn wheel has worn this much:
  // below the 6 mm of the warning alarm, as a depot plans.
  double depot_reprofile_wear_mm = 4.2;
  double drift_rate_low_v_per_day = 0.008;  // |ageing drift| of a drifting sensor, uniform
  double drift_rate_high_v_per_day = 0.02;
  double ambient_mean_c = 30.0;      // seasonal ambient: mean + amplitude sin(2 pi (doy - 105)/365)
  double ambient_amplitude_c = 6.0;  // (hottest in July on the Ethio-Djibouti line)
};

struct WheelTruth {
  int channel = 0;  // 0 to 11 (docs/locomotive.md)
  double wear_rate_mm_per_1000km = 0.0;
  double initial_wear_mm = 0.0;      // at the start of day 0
  std::vector<int> reprofiled_days;  // days (from 0) on which the depot reprofiled it
  // Read from a truth file that states them (another reality's, whose days cannot be drawn
  // again here): the days (from 0) its flange reaches TruthLimitDates' limits; none within the
  // horizon. The fleet scenario's own are worked out from its seed instead (fleet_truth_check.h).
  std::optional<int> warning_day, critical_day;
};

// The limits a truth file's own dates are for, and how far they were looked for.
struct TruthLimitDates {
  double warning_clearance_mm = 0.0;
  double critical_clearance_mm = 0.0;
  int horizon_days = 0;  // from day 0: a date past it is not known
};

struct LocomotiveTruth {
  std::string name;                // "L01", "L02", ...
  std::vector<double> day_km;      // distance run each day; 0 on depot days
  std::vector<WheelTruth> wheels;  // 12, in channel order
  // Flange wear (mm) of every wheel at the start of each day's service: wear_mm[day][channel].
  std::vector<std::vector<double>> wear_mm;
};

struct SensorDrift {
  int locomotive = 0;  // index into FleetTruth::locomotives
  int channel = 0;
  int start_day = 0;            // the offset creeps from the start of this day ...
  double rate_v_per_day = 0.0;  // ... at this rate (the twin's ageing_drift)
};

struct FleetTruth {
  FleetSettings settings;
  FleetDraws draws;
  std::vector<double> ambient_c;  // per day
  std::vector<LocomotiveTruth> locomotives;
  std::vector<SensorDrift> drifts;
  std::optional<TruthLimitDates> limit_dates;  // read from a file that states its dates
};

// Draws the fleet. Throws BadArgument naming the setting and its valid range.
FleetTruth plan_fleet(const FleetSettings& settings, const FleetDraws& draws = {});

// The drift of (locomotive, channel), or nullptr when that sensor is healthy.
const SensorDrift* drift_of(const FleetTruth& truth, int locomotive, int channel);

// "YYYY-MM-DD" of `day` days since 1970-01-01.
std::string iso_date(int day);

}  // namespace flange::sim
