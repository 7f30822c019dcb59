// SPDX-License-Identifier: MIT
// The rows of the measurement store as C++ values: what a caller writes and what it reads back.
// Times are ISO 8601 UTC text ("2026-03-01T06:00:00Z"): they sort as text on both backends.
// A wheel is named by its locomotive, axle (1 = leading) and side ("left" or "right").
#pragma once

#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace flange::host {

enum class SessionKind { kBench, kService };

// "bench" or "service".
const char* session_kind_name(SessionKind kind);

struct WheelKey {
  std::string locomotive;
  int axle = 1;               // 1 to 6
  std::string side = "left";  // "left" or "right"
  bool operator==(const WheelKey&) const = default;
};

// The channel a wheel is on when nothing says otherwise: the two wheels of axle 1 on 0 (left)
// and 1 (right), and so on to axle 6 on 10 and 11 (the loco scenario's order).
int default_channel(const WheelKey& wheel);

struct LocomotiveRecord {
  std::string name;         // unique
  std::string description;  // free text
};

struct WheelRecord {
  WheelKey wheel;
  int channel = 0;  // the on-board unit's channel, 0 to 11
};

// A sensor (by its serial) fitted to a wheel at a time; every refit to another wheel is kept.
struct SensorRecord {
  std::string serial;  // unique
  std::string model;   // free text, e.g. "inductive LVDT-20"
  std::optional<WheelKey> fitted_to;
  std::string fitted_at;  // when it was fitted to `fitted_to`
};

// One bench or service session: a recording as it came in.
struct SessionRecord {
  SessionKind kind = SessionKind::kService;
  std::string label;       // the run label (bench) or the recording's name (service)
  std::string started_at;  // UTC
  double sample_rate_hz = 0.0;
  std::string source_file;  // as given
  std::string source_sha256;
  std::string sensor_serial;  // "" when unknown
};

// One bench row as kept (bench sessions keep every row: the regression is refitted from them).
struct BenchRow {
  double t_s = 0.0;
  std::optional<double> clearance_mm;
  double temp_c = 0.0;
  double voltage_v = 0.0;
};

// A fitted calibration; every refit is a new one, with the sessions it was fitted on.
struct CalibrationRecord {
  std::string fitted_at;      // UTC
  std::string sensor_serial;  // "" for a calibration not tied to one sensor
  std::string model_json;     // the whole model.json
  std::uint64_t rows = 0;     // rows fitted
  double rmse_mm = 0.0;
  std::vector<std::int64_t> session_ids;
};

// One wheel's figures from one run. The wear is the caller's estimate; the store keeps it.
struct WheelRunResult {
  int axle = 1;
  std::string side = "left";
  int channel = 0;
  std::optional<double> wear_mm;       // flange wear: clearance_mm - the gap over a new flange
  std::optional<double> clearance_mm;  // static clearance at reference conditions
  double temp_c = 0.0;                 // mean temperature
  std::uint64_t samples = 0;
  std::uint64_t flagged_samples = 0;
  std::string final_alarm = "none";
  std::optional<double> mae_before_mm, mae_after_mm;  // against a reference, when there is one
};

struct AlarmEventRecord {
  int axle = 0;  // 0 with side "" for a run not tied to a wheel
  std::string side;
  double t_s = 0.0;  // time in the recording
  std::string what;  // "warning", "critical", "none" (cleared), "wear_step 0.73 mm"
};

// The reduced trace of a service run: per wheel, per kilometre of the run, the means.
struct TracePoint {
  int axle = 0;
  std::string side;
  double km = 0.0;  // start of the kilometre bin, from the run's start
  double clearance_mm = 0.0;
  double temp_c = 0.0;
  std::uint64_t samples = 0;
};

struct RunRecord {
  std::string locomotive;  // "" for a run not tied to a locomotive (no wheel rows then)
  std::optional<std::int64_t> session_id;
  // Without session_id: the run's session, written in the run's transaction (or found, when
  // the same session is stored already).
  std::optional<SessionRecord> session;
  std::string started_at;       // UTC
  double distance_km = 0.0;     // this run's distance
  double odometer_km = 0.0;     // the locomotive's odometer at the end of the run
  std::string coefficient_set;  // the filter.json as given
  std::string coefficient_sha256;
  std::optional<std::int64_t> calibration_id;
  std::string engine;  // "model", "rtl", "float", "board"
  double sample_rate_hz = 0.0;
  std::uint64_t rows = 0, flagged_rows = 0, bad_rows = 0;
  std::string final_alarm = "none";
  std::string summary_json;  // the run's whole summary.json, for anything not a column
  std::vector<WheelRunResult> wheels;
  std::vector<AlarmEventRecord> alarms;
  std::vector<TracePoint> trace;
};

struct MaintenanceRecord {
  WheelKey wheel;
  std::string at;  // UTC
  double odometer_km = 0.0;
  std::string kind = "reprofile";
  std::string note;              // the depot's own words, free text
  std::optional<int> from_axle;  // wheelset_moved: the axle it ran on before, 1 to 6
};

// ---- read back ----

// One point of a wheel's wear history (one run).
struct WearPoint {
  std::int64_t run_id = 0;
  std::string started_at;
  double odometer_km = 0.0;
  std::optional<double> wear_mm;
  std::optional<double> clearance_mm;
  double temp_c = 0.0;
  std::uint64_t samples = 0;
  std::string final_alarm;
  std::string sensor_serial;  // the sensor fitted at the time ("" when none recorded)
};

// One run of a wheel as the wear estimate reads it (Store::wear_series).
struct SeriesPoint {
  std::int64_t run_id = 0;
  std::string started_at;
  double odometer_km = 0.0;
  std::optional<double> wear_mm;
  std::optional<double> clearance_mm;
};

// Every run of one wheel, in time order.
struct WheelSeries {
  WheelRecord wheel;
  std::vector<SeriesPoint> points;
};

struct StoredWheel {
  WheelRecord wheel;
  std::string sensor_serial;  // the sensor fitted now ("" when none)
};

struct StoredAlarmEvent {
  std::int64_t run_id = 0;
  std::string run_started_at;
  std::optional<WheelKey> wheel;
  double t_s = 0.0;
  std::string what;
};

struct StoredMaintenance {
  std::int64_t id = 0;
  MaintenanceRecord event;
};

// One row of the fleet table: a wheel's runs summarised by the database (per-wheel sums the
// writes keep: one row per wheel is read). The rate is the least-squares slope of wear against
// odometer over the runs at or after the wheel's latest maintenance event (all runs when there
// is none), in mm per 1000 km.
struct FleetRow {
  WheelKey wheel;
  std::uint64_t runs = 0;  // all runs
  std::uint64_t runs_since_maintenance = 0;
  std::string last_run_at;
  double last_odometer_km = 0.0;
  std::optional<double> last_wear_mm;
  std::optional<double> wear_rate_mm_per_1000km;  // needs two runs at distinct odometers
  std::optional<double> wear_rate_se;             // its standard error; needs three runs
  std::string last_maintenance_at;                // "" when none
  std::uint64_t alarm_events = 0;
};

// One wheel's wear estimate as `flange wear` made it (host/wear/fleet_wear.h), kept so that a
// reprofiling plan can be made at any risk without reading every run again: the rate with its
// interval, standard error and degrees of freedom, the fitted clearance and wear at the last run,
// the locomotive's km per day and what the forecast of the limits was made from.
struct WheelEstimateRecord {
  WheelKey wheel;
  int channel = 0;
  std::string status;         // the estimator's: "ok", "sensor fault", ...
  bool has_fit = false;       // a wear line (and so a forecast) was fitted
  std::string segment_start;  // the first run of the current flange ("" without runs)
  std::string last_run_at;    // the wheel's last run
  double last_run_day = 0.0;  // the same in days since 1970-01-01
  double rate_mm_per_1000km = 0.0, rate_low = 0.0, rate_high = 0.0;  // 95 % interval
  double rate_se = 0.0;
  int rate_dof = 0;
  int fit_dof = 0;  // the wear line's own (used when rate_dof is 0)
  double clearance_now_mm = 0.0, wear_now_mm = 0.0;
  double km_per_day = 0.0;
  double km_per_day_se = 0.0, day_km_sd = 0.0;
  int km_per_day_dof = 0;
  double clearance_now_se_mm = 0.0, clearance_rate_covariance = 0.0;
  bool critical_reached = false;
  std::string critical_date, warning_date;  // at the fitted rate; "" when unknown
  // The wheel's sensor flag carried to the next estimate (host/wear/sensor_flag_latch.h,
  // schema version 6): the wheel's last run at the estimate that first flagged its sensor and
  // at the one that confirmed it ("" when none, or while pending).
  std::string sensor_flag_first, sensor_flag_confirmed;
  // The dates' whole forecast input as JSON (host/wear/limit_forecast.h, ForecastInput; schema
  // version 7; cli/stored_wear_estimates.cpp writes and reads it), so the plan from the store is
  // the same quantile of the same forecast. "" when not kept: an estimate stored before version
  // 7 is planned on the rate's quantile alone, as it was then.
  std::string forecast;
};

// What the store held when a set of estimates was made: a set is current while these are the
// store's latest (no run, maintenance event or calibration stored since).
struct StoreMarks {
  std::int64_t last_run_id = 0;
  std::int64_t last_maintenance_id = 0;
  std::int64_t last_calibration_id = 0;
  bool operator==(const StoreMarks&) const = default;
};

// Every wheel's estimate from one `flange wear`, with the settings it was made with.
struct WearEstimateSet {
  std::string made_at;  // ISO 8601 UTC
  StoreMarks marks;     // the store's when the runs were read
  double warning_clearance_mm = 0.0, critical_clearance_mm = 0.0, max_step_mm = 0.0;
  std::vector<WheelEstimateRecord> wheels;  // by locomotive, axle, side
};

}  // namespace flange::host
