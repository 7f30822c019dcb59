// SPDX-License-Identifier: MIT
// The second fleet reality's depot, day by day: what each locomotive ran, where, in which
// weather, how every flange wore and what the depot did. Drawn from one seed; nothing here is
// taken from the fleet scenario of sim/ (README.md gives the laws and why they differ).
//
// Wear of the wheel on axle a, side s, per km (mm per 1000 km):
//   rate = base_wheel share_a (0.45 + 2.2 curve_share hand_share_s 600 / R_mid)
//          (1 + 0.015 (T_ambient - 22)) exp(0.06 wear)
// base_wheel lognormal (median 0.055, sigma 0.3) and carried by the wheel when its wheelset
// moves; share_a 1.3 on a bogie's leading axle, 0.75 in the middle, 1 trailing; hand_share_s
// the share of the route's curves that throw this wheel's flange against the rail (the left
// wheel in right-hand curves); a thinner flange wears faster (exp(0.06 wear)).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fleet_alt_sensor.h"
#include "fleet_alt_track.h"

namespace flange::fleet_alt {

inline constexpr int kWheels = 12;  // channel c: axle c / 2 + 1, left (even) or right (odd)
inline constexpr int kMaxLocomotives = 50;
inline constexpr int kMinDays = 21;  // room for every depot event before and after it
inline constexpr int kMaxDays = 1095;
inline constexpr double kNewFlangeClearanceMm = 2.0;  // the sensor's setting over a new flange
// How far the world goes on after the recorded period for the truth's limit dates: ten years from
// day 0, the calendar the fleet scenario's own true dates run over; a flange that reaches a limit
// only later has no date (fleet_alt_limits.h).
inline constexpr int kTruthHorizonDays = 3650;

struct FleetAltSettings {
  int locomotives = 4;  // 1 to kMaxLocomotives
  int days = 365;       // kMinDays to kMaxDays
  std::uint64_t seed = 0;
  int start_day = 20878;       // day 0: 2027-03-01, in days since 1970-01-01
  double recording_s = 300.0;  // each morning's recording, 60 to 3600 s
  double fs_hz = 6.0;          // its sample rate, 1 to 100 Hz
};

enum class DepotEventKind { kReprofile, kSensorReplaced, kWheelsetMoved, kOdometerReset };

// "reprofile", "sensor_replaced", "wheelset_moved", "odometer_reset": the store's kinds.
const char* depot_event_name(DepotEventKind kind);

// One thing the depot did and wrote down (at noon of a depot day).
struct DepotEvent {
  int day = 0;
  int locomotive = 0;
  DepotEventKind kind = DepotEventKind::kReprofile;
  int axle = 0;                      // 1 to 6; 0: the whole locomotive (odometer reset)
  int side = -1;                     // 0 left, 1 right, -1 both wheels of the axle
  int from_axle = 0;                 // wheelset moved: where it ran before
  double odometer_reading_km = 0.0;  // the odometer as read then (before a reset)
  std::string sensor_serial;         // sensor replaced: the new unit
};

struct WheelOnDay {
  double wear_mm = 0.0;   // the flange's wear at the start of the day's service
  double mount_mm = 0.0;  // the sensor's mounting error (its clearance over a new flange - 2 mm)
  SensorUnit unit;
  std::string serial;
  double coil_offset_c = 0.0;  // this wheel's own heating
};

struct LocomotiveDay {
  int day = 0;
  double km = 0.0;        // run that day (0: in the depot)
  bool recorded = false;  // ran and its recorder kept the morning's recording
  double start_hour = 6.0;
  int route = 0;  // index into FleetAltTruth::routes
  double track_start_m = 0.0;
  double odometer_reading_km = 0.0;  // at the start of the day's service
  double parked_rise_c = 0.0;
  std::array<WheelOnDay, kWheels> wheels;
};

// What is true of one wheel position (channel) over the days.
struct PositionTruth {
  double initial_wear_mm = 0.0;
  std::vector<int> reprofiled_days;
  std::vector<double> accrued_mm;  // per day: the wear the position's flange gained
  std::vector<double> base_rate;   // per day: the base rate of the wheel that ran there
  // The days (from day 0) on which the flange that ran here on the locomotive's last recorded
  // day reaches the warning and the critical limit (fleet_alt_limits.h); none within
  // kTruthHorizonDays.
  std::optional<int> warning_day, critical_day;
};

// A day after the recorded period, drawn on from the locomotive's own stream: its route and km
// (0: in the depot). Nothing is recorded and the depot turns, moves and refits nothing.
struct DayAfter {
  int route = 0;
  double km = 0.0;
};

struct DriftTruth {
  int locomotive = 0, channel = 0, start_day = 0;
  double rate_v_per_day = 0.0;
};

struct LocomotiveHistory {
  std::string name;  // "A01", "A02", ...
  std::vector<LocomotiveDay> days;
  std::array<PositionTruth, kWheels> positions;
  std::vector<DayAfter> days_after;  // from the period's end to kTruthHorizonDays
};

struct FleetAltTruth {
  FleetAltSettings settings;
  std::vector<RouteTrack> routes;
  std::vector<double> ambient_c;        // per day of the period
  std::vector<double> ambient_after_c;  // per day after it, to kTruthHorizonDays
  std::vector<LocomotiveHistory> locomotives;
  std::vector<DepotEvent> events;  // in day order
  DriftTruth drift;
};

// Draws the whole fleet. Throws std::invalid_argument naming the setting and its valid range.
FleetAltTruth plan_fleet_alt(const FleetAltSettings& settings);

// The wear rate (mm per 1000 km) of the position's flanges between its first and last recorded
// days: the wear they gained over the km run in between (the flange there may change).
double position_rate_mm_per_1000km(const LocomotiveHistory& loco, int channel);

// The wear law above (mm per 1000 km) of the wheel on `axle` (1-6), `side` (0 left, 1 right).
double wear_rate_mm_per_1000km(const RouteKind& route, int axle, int side, double base,
                               double wear_mm, double ambient_c);

// "YYYY-MM-DD" of `day` days since 1970-01-01.
std::string date_text(int day);

}  // namespace flange::fleet_alt
