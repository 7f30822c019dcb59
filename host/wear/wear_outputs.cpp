// SPDX-License-Identifier: MIT
#include "wear_outputs.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace flange::host {
namespace {

using nlohmann::ordered_json;

ordered_json optional_number(const std::optional<double>& value) {
  return value ? ordered_json(*value) : ordered_json(nullptr);
}

ordered_json forecast_json(const LimitForecast& forecast) {
  return {{"limit_clearance_mm", forecast.limit_clearance_mm},
          {"reached", forecast.reached},
          {"km", optional_number(forecast.km)},
          {"km_low", optional_number(forecast.km_low)},
          {"km_high", optional_number(forecast.km_high)},
          {"days", optional_number(forecast.days)},
          {"days_low", optional_number(forecast.days_low)},
          {"days_high", optional_number(forecast.days_high)},
          {"date", forecast.date},
          {"date_low", forecast.date_low},
          {"date_high", forecast.date_high}};
}

ordered_json runs_json(const WheelWear& wheel) {
  ordered_json runs = ordered_json::array();
  for (std::size_t k = 0; k < wheel.runs.size(); ++k) {
    const WearObservation& run = wheel.runs[k];
    runs.push_back({{"run_id", run.run_id},
                    {"at", run.at},
                    {"odometer_km", run.odometer_km},
                    {"clearance_mm", run.clearance_mm},
                    {"segment", wheel.segment.empty() ? 0 : wheel.segment[k]}});
  }
  return runs;
}

ordered_json wheel_json(const WheelWear& wheel) {
  ordered_json reprofilings = ordered_json::array();
  for (const ReprofilingEvent& event : wheel.reprofilings) {
    reprofilings.push_back({{"last_run_before", event.last_run_before},
                            {"first_run_after", event.first_run_after},
                            {"odometer_km", event.odometer_km},
                            {"found_in_data", event.found},
                            {"recorded", event.recorded},
                            {"recorded_at", event.recorded_at}});
  }
  ordered_json fault = nullptr;
  if (wheel.sensor_fault) {
    fault = {{"onset", date_of_day(wheel.sensor_fault->onset_day)},
             {"drift_mm_per_day", wheel.sensor_fault->rate_mm_per_day},
             {"drift_by_last_run_mm", wheel.sensor_fault->size_mm},
             {"t_statistic", wheel.sensor_fault->difference_t},
             {"found_in", wheel.sensor_fault->in_sum ? "sum" : "difference"}};
  }
  ordered_json flag = nullptr;
  if (wheel.sensor_flag) {
    flag = {{"first_flagged", wheel.sensor_flag->first_flagged},
            {"confirmed", wheel.sensor_flag->latched() ? ordered_json(wheel.sensor_flag->confirmed)
                                                       : ordered_json(nullptr)},
            {"latched", wheel.sensor_flag->latched()}};
  }
  return {{"locomotive", wheel.wheel.locomotive},
          {"axle", wheel.wheel.axle},
          {"side", wheel.wheel.side},
          {"channel", wheel.wheel.channel},
          {"status", wheel.status},
          {"wear_rate_mm_per_1000km", wheel.rate_mm_per_1000km},
          {"wear_rate_low", wheel.rate_low},
          {"wear_rate_high", wheel.rate_high},
          {"wear_rate_se", wheel.rate_se},
          {"interval_dof", wheel.rate_dof},
          {"clearance_now_mm", wheel.clearance_now_mm},
          {"wear_now_mm", wheel.wear_now_mm},
          {"km_per_day", wheel.km_per_day},
          {"warning", forecast_json(wheel.warning)},
          {"critical", forecast_json(wheel.critical)},
          {"sensor_fault", fault},
          {"sensor_flag", flag},
          {"reprofilings", reprofilings},
          {"runs", runs_json(wheel)}};
}

// The fleet's bend and calendar trend (wear_acceleration.h) the dates were made with; null when
// the fleet could not estimate them.
ordered_json acceleration_json(const FleetAcceleration& bend) {
  if (bend.dof == 0) return nullptr;
  return {{"per_mm", bend.estimate},
          {"per_mm_se", bend.se},
          {"per_mm_in_dates", acceleration_in_dates(bend)},
          {"trend_per_day", bend.trend},
          {"trend_per_day_se", bend.trend_se},
          {"covariance", bend.covariance},
          {"dof", bend.dof},
          {"differs_from_zero", bend.significant}};
}

}  // namespace

std::string interval_text(const std::optional<double>& value, const std::optional<double>& low,
                          const std::optional<double>& high, int decimals) {
  if (!value) return "-";
  return fmt::format("{:.{}f} [{}, {}]", *value, decimals,
                     low ? fmt::format("{:.{}f}", *low, decimals) : "-",
                     high ? fmt::format("{:.{}f}", *high, decimals) : "inf");
}

void write_wear_json(const std::filesystem::path& path, const FleetWear& fleet,
                     const std::string& generated_by) {
  ordered_json wheels = ordered_json::array();
  for (const WheelWear& wheel : fleet.wheels) wheels.push_back(wheel_json(wheel));
  const ordered_json json = {{"generated_by", generated_by},
                             {"warning_clearance_mm", fleet.warning_clearance_mm},
                             {"critical_clearance_mm", fleet.critical_clearance_mm},
                             {"sensor_gap_mm", fleet.thresholds.sensor_gap_mm},
                             {"max_step_mm", fleet.thresholds.max_step_mm},
                             {"fleet_acceleration", acceleration_json(fleet.acceleration)},
                             {"wheels", wheels}};
  std::ofstream file(path, std::ios::binary);
  file << json.dump(1) << "\n";
  file.close();
  if (!file) throw std::runtime_error(path.string() + ": cannot write");
}

void write_wear_csv(const std::filesystem::path& path, const FleetWear& fleet) {
  std::ofstream csv(path, std::ios::binary);
  csv << "locomotive,axle,side,channel,status,runs,reprofilings,wear_now_mm,"
         "wear_rate_mm_per_1000km,wear_rate_low,wear_rate_high,km_per_day,"
         "warning_km,warning_km_low,warning_km_high,warning_date,warning_date_low,"
         "warning_date_high,critical_km,critical_date,critical_date_low,critical_date_high\n";
  const auto number = [](const std::optional<double>& v) {
    return v ? fmt::format("{:.1f}", *v) : std::string();
  };
  for (const WheelWear& w : fleet.wheels) {
    csv << fmt::format(
        "{},{},{},{},{},{},{},{:.4f},{:.4f},{:.4f},{:.4f},{:.1f},{},{},{},{},{},{},{},{},{},{}\n",
        w.wheel.locomotive, w.wheel.axle, w.wheel.side, w.wheel.channel, w.status, w.runs.size(),
        w.reprofilings.size(), w.wear_now_mm, w.rate_mm_per_1000km, w.rate_low, w.rate_high,
        w.km_per_day, number(w.warning.km), number(w.warning.km_low), number(w.warning.km_high),
        w.warning.date, w.warning.date_low, w.warning.date_high, number(w.critical.km),
        w.critical.date, w.critical.date_low, w.critical.date_high);
  }
  csv.close();
  if (!csv) throw std::runtime_error(path.string() + ": cannot write");
}

std::string fleet_wear_text(const FleetWear& fleet) {
  std::string text = fmt::format("  {:<5} {:<12} {:>4} {:>3} {:>7}  {:<26} {:<12} {:<36} {}\n",
                                 "loco", "wheel", "runs", "rep", "wear_mm", "rate mm/1000km [95 %]",
                                 "status", "warning date [95 %]", "critical date");
  for (const WheelWear& w : fleet.wheels) {
    const std::string warning =
        w.warning.reached
            ? "reached"
            : fmt::format("{} [{}, {}]", w.warning.date.empty() ? "-" : w.warning.date,
                          w.warning.date_low.empty() ? "-" : w.warning.date_low,
                          w.warning.date_high.empty() ? "-" : w.warning.date_high);
    text += fmt::format(
        "  {:<5} {:<12} {:>4} {:>3} {:>7.3f}  {:<26} {:<12} {:<36} {}\n", w.wheel.locomotive,
        fmt::format("axle {} {}", w.wheel.axle, w.wheel.side), w.runs.size(), w.reprofilings.size(),
        w.wear_now_mm,
        w.fit
            ? fmt::format("{:.4f} [{:.4f}, {:.4f}]", w.rate_mm_per_1000km, w.rate_low, w.rate_high)
            : std::string("-"),
        w.status, warning,
        w.critical.reached ? "reached" : (w.critical.date.empty() ? "-" : w.critical.date));
  }
  for (const WheelWear& w : fleet.wheels) {
    if (!w.sensor_flag) continue;
    text += fmt::format(
        "  {} axle {} {}: sensor {}{}\n", w.wheel.locomotive, w.wheel.axle, w.wheel.side,
        sensor_flag_text(*w.sensor_flag),
        w.sensor_flag->latched() ? " (held until a maintenance event on the wheel)" : "");
  }
  return text;
}

}  // namespace flange::host
