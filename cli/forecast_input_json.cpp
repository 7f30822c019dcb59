// SPDX-License-Identifier: MIT
#include "forecast_input_json.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <utility>
#include <vector>

namespace flange::cli {
namespace {

// Every real field by name.
std::vector<std::pair<const char*, double host::ForecastInput::*>> real_fields() {
  using F = host::ForecastInput;
  return {{"clearance_now_mm", &F::clearance_now_mm},
          {"rate_mm_per_km", &F::rate_mm_per_km},
          {"rate_low_mm_per_km", &F::rate_low_mm_per_km},
          {"rate_high_mm_per_km", &F::rate_high_mm_per_km},
          {"km_per_day", &F::km_per_day},
          {"last_day", &F::last_day},
          {"clearance_now_se_mm", &F::clearance_now_se_mm},
          {"rate_se_mm_per_km", &F::rate_se_mm_per_km},
          {"clearance_rate_covariance", &F::clearance_rate_covariance},
          {"km_per_day_se", &F::km_per_day_se},
          {"day_km_long_run_sd", &F::day_km_long_run_sd},
          {"acceleration_per_mm", &F::acceleration_per_mm},
          {"clearance_per_acceleration", &F::clearance_per_acceleration},
          {"rate_per_acceleration", &F::rate_per_acceleration},
          {"clearance_per_trend", &F::clearance_per_trend},
          {"rate_per_trend", &F::rate_per_trend},
          {"acceleration_se", &F::acceleration_se},
          {"trend_se", &F::trend_se},
          {"acceleration_trend_covariance", &F::acceleration_trend_covariance}};
}

// ... and every integer one.
std::vector<std::pair<const char*, int host::ForecastInput::*>> integer_fields() {
  using F = host::ForecastInput;
  return {{"dof", &F::dof},
          {"km_per_day_dof", &F::km_per_day_dof},
          {"acceleration_dof", &F::acceleration_dof}};
}

// The rate to come's (host/wear/season_to_come.h, weekly_wear_rate.h) and the season carried
// forward: absent from the estimates kept before they were in the dates, and read as 0 then.
std::vector<std::pair<const char*, double host::ForecastInput::*>> rate_to_come_fields() {
  using F = host::ForecastInput;
  return {{"season_variance", &F::season_variance},
          {"rate_long_run_variance", &F::rate_long_run_variance},
          {"season_trend_per_day", &F::season_trend_per_day},
          {"season_departure_days", &F::season_departure_days}};
}

}  // namespace

std::string forecast_input_json(const host::ForecastInput& input) {
  nlohmann::json json = nlohmann::json::object();
  for (const auto& [name, field] : real_fields()) json[name] = input.*field;
  for (const auto& [name, field] : integer_fields()) json[name] = input.*field;
  for (const auto& [name, field] : rate_to_come_fields()) json[name] = input.*field;
  json["rate_long_run_dof"] = input.rate_long_run_dof;
  return json.dump();
}

host::ForecastInput forecast_input_of_json(const std::string& text) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, false);
  if (!json.is_object()) throw std::invalid_argument("forecast: not a JSON object");
  host::ForecastInput input;
  for (const auto& [name, field] : real_fields()) {
    const auto value = json.find(name);
    // null: a non-finite number, as JSON writes it.
    if (value == json.end() || !(value->is_number() || value->is_null())) {
      throw std::invalid_argument(std::string("forecast: ") + name + " is not a number");
    }
    input.*field = value->is_null() ? NAN : value->get<double>();
  }
  // Kept before the rate to come or the season carried forward was in the dates: none.
  for (const auto& [name, field] : rate_to_come_fields()) {
    const auto value = json.find(name);
    if (value != json.end() && value->is_number()) input.*field = value->get<double>();
  }
  const auto duty_dof = json.find("rate_long_run_dof");
  if (duty_dof != json.end() && duty_dof->is_number_integer()) {
    input.rate_long_run_dof = duty_dof->get<int>();
  }
  for (const auto& [name, field] : integer_fields()) {
    const auto value = json.find(name);
    if (value == json.end() || !value->is_number_integer()) {
      throw std::invalid_argument(std::string("forecast: ") + name + " is not an integer");
    }
    input.*field = value->get<int>();
  }
  return input;
}

}  // namespace flange::cli
