// SPDX-License-Identifier: MIT
#include "fleet_truth_file.h"

#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "locomotive_wheels.h"
#include "sim_error.h"

namespace flange::sim {
namespace {

using nlohmann::ordered_json;

ordered_json wheel_json(const WheelTruth& wheel, int start_day) {
  const WheelPosition position = wheel_position(wheel.channel);
  ordered_json days = ordered_json::array();
  for (const int day : wheel.reprofiled_days) days.push_back(iso_date(start_day + day));
  return {{"channel", wheel.channel},
          {"axle", position.axle},
          {"side", side_name(position.side)},
          {"wear_rate_mm_per_1000km", wheel.wear_rate_mm_per_1000km},
          {"initial_wear_mm", wheel.initial_wear_mm},
          {"reprofiled", days}};
}

ordered_json locomotive_json(const LocomotiveTruth& loco, int start_day) {
  ordered_json wheels = ordered_json::array();
  for (const WheelTruth& wheel : loco.wheels) wheels.push_back(wheel_json(wheel, start_day));
  return {{"name", loco.name}, {"day_km", loco.day_km}, {"wheels", wheels}};
}

int day_number(const std::string& date, const std::string& where) {
  int y = 0, m = 0, d = 0;
  if (std::sscanf(date.c_str(), "%4d-%2d-%2d", &y, &m, &d) != 3) {
    throw BadArgument(where + ": '" + date + "' is not a date YYYY-MM-DD");
  }
  using namespace std::chrono;
  return static_cast<int>(
      sys_days{year{y} / month{static_cast<unsigned>(m)} / day{static_cast<unsigned>(d)}}
          .time_since_epoch()
          .count());
}

// A wheel's stated date (days from day 0), when the file has it and it is not null.
std::optional<int> optional_day(const nlohmann::json& wheel, const char* field, int start_day,
                                const std::string& where) {
  if (!wheel.contains(field) || wheel.at(field).is_null()) return std::nullopt;
  return day_number(wheel.at(field).get<std::string>(), where) - start_day;
}

}  // namespace

void write_fleet_truth(const std::filesystem::path& path, const FleetTruth& truth,
                       const FleetRecording& recording, const std::string& generated_by) {
  const int start = truth.settings.start_day;
  ordered_json locomotives = ordered_json::array();
  for (const LocomotiveTruth& loco : truth.locomotives) {
    locomotives.push_back(locomotive_json(loco, start));
  }
  ordered_json drifts = ordered_json::array();
  for (const SensorDrift& drift : truth.drifts) {
    const WheelPosition position = wheel_position(drift.channel);
    drifts.push_back({{"locomotive", truth.locomotives.at(drift.locomotive).name},
                      {"channel", drift.channel},
                      {"axle", position.axle},
                      {"side", side_name(position.side)},
                      {"start", iso_date(start + drift.start_day)},
                      {"rate_v_per_day", drift.rate_v_per_day}});
  }
  const ordered_json json = {{"generated_by", generated_by},
                             {"seed", truth.settings.seed},
                             {"first_day", iso_date(start)},
                             {"days", truth.settings.days},
                             {"recording",
                              {{"fs_hz", recording.fs_hz},
                               {"duration_s", recording.duration_s},
                               {"route_tangent_out_m", recording.route_tangent_out_m},
                               {"new_flange_clearance_mm", recording.new_flange_clearance_mm}}},
                             {"locomotives", locomotives},
                             {"drifting_sensors", drifts}};
  std::ofstream file(path, std::ios::binary);
  file << json.dump(1) << "\n";
  file.close();
  if (!file) throw std::runtime_error(path.string() + ": cannot write the truth file");
}

FleetTruth read_fleet_truth(const std::filesystem::path& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw BadArgument(path.string() + ": cannot open the truth file");
  const std::string where = path.string();
  try {
    const nlohmann::json json = nlohmann::json::parse(file);
    FleetTruth truth;
    truth.settings.seed = json.at("seed").get<std::uint64_t>();
    truth.settings.days = json.at("days").get<int>();
    truth.settings.start_day = day_number(json.at("first_day").get<std::string>(), where);
    for (const nlohmann::json& l : json.at("locomotives")) {
      LocomotiveTruth loco;
      loco.name = l.at("name").get<std::string>();
      loco.day_km = l.at("day_km").get<std::vector<double>>();
      for (const nlohmann::json& w : l.at("wheels")) {
        WheelTruth wheel;
        wheel.channel = w.at("channel").get<int>();
        wheel.wear_rate_mm_per_1000km = w.at("wear_rate_mm_per_1000km").get<double>();
        wheel.initial_wear_mm = w.at("initial_wear_mm").get<double>();
        for (const nlohmann::json& d : w.at("reprofiled")) {
          wheel.reprofiled_days.push_back(day_number(d.get<std::string>(), where) -
                                          truth.settings.start_day);
        }
        wheel.warning_day = optional_day(w, "true_warning_date", truth.settings.start_day, where);
        wheel.critical_day = optional_day(w, "true_critical_date", truth.settings.start_day, where);
        loco.wheels.push_back(wheel);
      }
      truth.locomotives.push_back(loco);
    }
    if (json.contains("limit_dates")) {
      const nlohmann::json& limits = json.at("limit_dates");
      TruthLimitDates dates;
      dates.warning_clearance_mm = limits.at("warning_clearance_mm").get<double>();
      dates.critical_clearance_mm = limits.at("critical_clearance_mm").get<double>();
      dates.horizon_days =
          day_number(limits.at("horizon").get<std::string>(), where) - truth.settings.start_day;
      truth.limit_dates = dates;
    }
    for (const nlohmann::json& d : json.at("drifting_sensors")) {
      SensorDrift drift;
      const std::string name = d.at("locomotive").get<std::string>();
      for (std::size_t k = 0; k < truth.locomotives.size(); ++k) {
        if (truth.locomotives[k].name == name) drift.locomotive = static_cast<int>(k);
      }
      drift.channel = d.at("channel").get<int>();
      drift.start_day =
          day_number(d.at("start").get<std::string>(), where) - truth.settings.start_day;
      drift.rate_v_per_day = d.at("rate_v_per_day").get<double>();
      truth.drifts.push_back(drift);
    }
    return truth;
  } catch (const nlohmann::json::exception& error) {
    throw BadArgument(fmt::format("{}: not a fleet truth file ({})", where, error.what()));
  }
}

}  // namespace flange::sim
