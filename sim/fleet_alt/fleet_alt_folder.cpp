// SPDX-License-Identifier: MIT
#include "fleet_alt_folder.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "fleet_alt_limits.h"
#include "fleet_alt_recording.h"

namespace flange::fleet_alt {
namespace {

namespace fs = std::filesystem;
using nlohmann::ordered_json;

std::string utc_text(int day, double hour) {
  const int minutes = static_cast<int>(std::lround(hour * 60.0));
  return fmt::format("{}T{:02d}:{:02d}:00Z", date_text(day), minutes / 60, minutes % 60);
}

void check_written(std::ofstream& file, const fs::path& path) {
  file.close();
  if (!file) throw std::runtime_error(path.string() + ": cannot write");
}

// Each recorded locomotive-day's folder and its line in runs.csv, in time order.
FleetAltWritten write_days(const FleetAltTruth& truth, const fs::path& dir,
                           const std::string& generated_by) {
  FleetAltWritten written;
  const fs::path runs_path = dir / "runs.csv";
  std::ofstream runs(runs_path, std::ios::binary);
  runs << "started_at,locomotive,manifest,distance_km,odometer_km\n";
  const int first = truth.settings.start_day;
  for (int day = 0; day < truth.settings.days; ++day) {
    std::map<std::string, std::string> lines;  // by start time: the day's runs in time order
    for (std::size_t l = 0; l < truth.locomotives.size(); ++l) {
      const LocomotiveHistory& loco = truth.locomotives[l];
      const LocomotiveDay& today = loco.days[static_cast<std::size_t>(day)];
      if (today.km == 0.0) ++written.depot_days;
      if (today.km > 0.0 && !today.recorded) ++written.missing_days;
      if (!today.recorded) continue;
      const fs::path folder = fs::path("days") / date_text(first + day) / loco.name;
      write_locomotive_day(truth, static_cast<int>(l), day, dir / folder, generated_by);
      const double km = recording_km(truth, today.route);
      const std::string started_at = utc_text(first + day, today.start_hour);
      lines[started_at + loco.name] =
          fmt::format("{},{},{},{:.3f},{:.3f}\n", started_at, loco.name,
                      (folder / "locomotive.json").string(), km, today.odometer_reading_km + km);
      ++written.runs;
    }
    for (const auto& [key, line] : lines) runs << line;
  }
  check_written(runs, runs_path);
  return written;
}

void write_maintenance(const FleetAltTruth& truth, const fs::path& dir) {
  const fs::path path = dir / "maintenance.csv";
  std::ofstream file(path, std::ios::binary);
  file << "at,locomotive,axle,side,kind,odometer_km,from_axle,sensor\n";
  for (const DepotEvent& event : truth.events) {
    file << fmt::format(
        "{},{},{},{},{},{:.3f},{},{}\n", utc_text(truth.settings.start_day + event.day, 12.0),
        truth.locomotives[static_cast<std::size_t>(event.locomotive)].name,
        event.axle > 0 ? std::to_string(event.axle) : "",
        event.side < 0 ? "" : (event.side == 0 ? "left" : "right"), depot_event_name(event.kind),
        event.odometer_reading_km, event.from_axle > 0 ? std::to_string(event.from_axle) : "",
        event.sensor_serial);
  }
  check_written(file, path);
}

// What happened at a wheel position beyond wear: for the truth's wheel kinds.
std::string position_kind(const FleetAltTruth& truth, int l, int channel) {
  if (truth.drift.locomotive == l && truth.drift.channel == channel) return "drifting sensor";
  for (const DepotEvent& event : truth.events) {
    if (event.locomotive != l || event.axle != channel / 2 + 1) continue;
    if (event.kind == DepotEventKind::kSensorReplaced && event.side == channel % 2) {
      return "sensor replaced";
    }
    if (event.kind == DepotEventKind::kWheelsetMoved) return "wheelset moved";
  }
  const auto& reprofiled = truth.locomotives[static_cast<std::size_t>(l)]
                               .positions[static_cast<std::size_t>(channel)]
                               .reprofiled_days;
  return reprofiled.empty() ? "healthy" : "reprofiled";
}

// A limit date, or null when it is past the horizon.
ordered_json date_json(const FleetAltTruth& truth, const std::optional<int>& day) {
  if (!day) return nullptr;
  return date_text(truth.settings.start_day + *day);
}

ordered_json locomotive_json(const FleetAltTruth& truth, int l) {
  const LocomotiveHistory& loco = truth.locomotives[static_cast<std::size_t>(l)];
  ordered_json wheels = ordered_json::array();
  for (int c = 0; c < kWheels; ++c) {
    const PositionTruth& position = loco.positions[static_cast<std::size_t>(c)];
    ordered_json days = ordered_json::array();
    for (const int day : position.reprofiled_days) {
      days.push_back(date_text(truth.settings.start_day + day));
    }
    wheels.push_back({{"channel", c},
                      {"axle", c / 2 + 1},
                      {"side", c % 2 == 0 ? "left" : "right"},
                      {"wear_rate_mm_per_1000km", position_rate_mm_per_1000km(loco, c)},
                      {"initial_wear_mm", position.initial_wear_mm},
                      {"reprofiled", days},
                      {"kind", position_kind(truth, l, c)},
                      {"true_warning_date", date_json(truth, position.warning_day)},
                      {"true_critical_date", date_json(truth, position.critical_day)}});
  }
  ordered_json day_km = ordered_json::array();
  for (const LocomotiveDay& day : loco.days) day_km.push_back(day.km);
  return {{"name", loco.name}, {"day_km", day_km}, {"wheels", wheels}};
}

void write_truth(const FleetAltTruth& truth, const fs::path& dir, const std::string& generated_by) {
  const FleetAltSettings& s = truth.settings;
  ordered_json locomotives = ordered_json::array();
  for (int l = 0; l < s.locomotives; ++l) locomotives.push_back(locomotive_json(truth, l));
  const DriftTruth& drift = truth.drift;
  const ordered_json drifts = ordered_json::array(
      {{{"locomotive", truth.locomotives[static_cast<std::size_t>(drift.locomotive)].name},
        {"channel", drift.channel},
        {"axle", drift.channel / 2 + 1},
        {"side", drift.channel % 2 == 0 ? "left" : "right"},
        {"start", date_text(s.start_day + drift.start_day)},
        {"rate_v_per_day", drift.rate_v_per_day}}});
  const ordered_json json = {{"generated_by", generated_by},
                             {"reality", "fleet-alt"},
                             {"seed", s.seed},
                             {"first_day", date_text(s.start_day)},
                             {"days", s.days},
                             {"recording",
                              {{"fs_hz", s.fs_hz},
                               {"duration_s", s.recording_s},
                               {"new_flange_clearance_mm", kNewFlangeClearanceMm}}},
                             {"limit_dates",
                              {{"warning_clearance_mm", kWarningClearanceMm},
                               {"critical_clearance_mm", kCriticalClearanceMm},
                               {"horizon", date_text(s.start_day + kTruthHorizonDays)}}},
                             {"locomotives", locomotives},
                             {"drifting_sensors", drifts}};
  const fs::path path = dir / "fleet_truth.json";
  std::ofstream file(path, std::ios::binary);
  file << json.dump(1) << "\n";
  check_written(file, path);
}

}  // namespace

FleetAltWritten write_fleet_alt_folder(const FleetAltTruth& truth, const fs::path& dir,
                                       const std::string& generated_by) {
  fs::create_directories(dir / "bench");
  for (int n = 1; n <= kBenchSessions; ++n) {
    write_bench_session(truth.settings, n, dir / "bench" / fmt::format("bench_{}.csv", n));
  }
  FleetAltWritten written = write_days(truth, dir, generated_by);
  write_maintenance(truth, dir);
  write_truth(truth, dir, generated_by);
  for (const DepotEvent& event : truth.events) {
    if (event.kind == DepotEventKind::kReprofile) ++written.reprofilings;
  }
  return written;
}

}  // namespace flange::fleet_alt
