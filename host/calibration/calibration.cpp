// SPDX-License-Identifier: MIT
#include "calibration.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "input_error.h"
#include "recording_csv.h"

namespace flange::host {

Calibration::Estimate Calibration::estimate(double voltage_v, double temp_c) const {
  Estimate e;
  e.clearance_mm = fit.model.clearance_mm(voltage_v, temp_c);
  e.outside_calibration = voltage_v < range.v_min || voltage_v > range.v_max ||
                          temp_c < range.t_min || temp_c > range.t_max;
  return e;
}

namespace {

// The rows of a database as they are read: every run label, the referenced rows to fit.
struct CalibrationInput {
  Calibration calibration;
  CalibrationData data;

  void add(const RecordingRow& row) {
    std::vector<std::string>& runs = calibration.runs;
    if (std::find(runs.begin(), runs.end(), row.run) == runs.end()) runs.push_back(row.run);
    if (!row.clearance_mm) {
      ++calibration.rows_without_reference;
      return;
    }
    data.voltage_v.push_back(row.voltage_v);
    data.temp_c.push_back(row.temp_c);
    data.clearance_mm.push_back(*row.clearance_mm);
  }

  Calibration fit(const std::string& source, const RegressionOptions& options) && {
    if (data.clearance_mm.empty()) {
      throw InputError(
          fmt::format("{}: no row has a clearance_mm reference to calibrate against", source));
    }
    try {
      calibration.fit = fit_regression(data, options);
    } catch (const InputError& error) {
      throw InputError(fmt::format("{}: {}", source, error.what()));
    }
    const auto [v_lo, v_hi] = std::minmax_element(data.voltage_v.begin(), data.voltage_v.end());
    const auto [t_lo, t_hi] = std::minmax_element(data.temp_c.begin(), data.temp_c.end());
    const auto [d_lo, d_hi] =
        std::minmax_element(data.clearance_mm.begin(), data.clearance_mm.end());
    calibration.range = {*v_lo, *v_hi, *t_lo, *t_hi, *d_lo, *d_hi};
    return std::move(calibration);
  }
};

}  // namespace

Calibration calibrate_database(const std::string& database_csv, const RegressionOptions& options) {
  RecordingReader reader(database_csv);
  CalibrationInput input;
  input.calibration.database = database_csv;
  while (const std::optional<RecordingRow> row = reader.next()) input.add(*row);
  input.calibration.rows = reader.rows_read();
  return std::move(input).fit(database_csv, options);
}

Calibration calibrate_rows(const std::string& source, const std::vector<RecordingRow>& rows,
                           const RegressionOptions& options) {
  CalibrationInput input;
  input.calibration.database = source;
  for (const RecordingRow& row : rows) input.add(row);
  input.calibration.rows = rows.size();
  return std::move(input).fit(source, options);
}

namespace {

std::string row_text(const RecordingRow& row, const std::string& run) {
  const std::string clearance = row.clearance_mm ? fmt::format("{}", *row.clearance_mm) : "";
  return fmt::format("{},{},{},{},{}\n", row.t_s, clearance, row.temp_c, row.voltage_v, run);
}

}  // namespace

std::size_t append_to_database(const std::string& database_csv, const std::string& new_csv) {
  namespace fs = std::filesystem;
  // Validate the addition completely before touching the database.
  std::vector<RecordingRow> added;
  {
    RecordingReader reader(new_csv);
    while (std::optional<RecordingRow> row = reader.next()) added.push_back(std::move(*row));
    if (added.empty()) throw InputError(fmt::format("{}: no data rows to append", new_csv));
  }
  const std::string new_label = fs::path(new_csv).stem().string();
  const std::string database_label = fs::path(database_csv).stem().string();
  const std::string temporary = database_csv + ".appending";
  {
    std::ofstream out(temporary, std::ios::binary);
    if (!out) throw std::runtime_error("cannot write " + temporary);
    out << "t_s,clearance_mm,temp_c,voltage_v,run\n";
    if (fs::exists(database_csv)) {
      RecordingReader existing(database_csv);
      while (const std::optional<RecordingRow> row = existing.next()) {
        out << row_text(*row, existing.has_run_column() ? row->run : database_label);
      }
    }
    bool new_has_run = false;
    {
      RecordingReader probe(new_csv);
      new_has_run = probe.has_run_column();
    }
    for (const RecordingRow& row : added) out << row_text(row, new_has_run ? row.run : new_label);
    if (!out) throw std::runtime_error("cannot write " + temporary);
  }
  try {
    RecordingReader check(temporary);
    while (check.next()) {
    }
  } catch (const InputError& error) {
    fs::remove(temporary);
    throw InputError(fmt::format(
        "{}: appending it to {} would break the database ({}); give the new session its own run "
        "label",
        new_csv, database_csv, error.what()));
  }
  fs::rename(temporary, database_csv);
  return added.size();
}

nlohmann::ordered_json calibration_json(const Calibration& calibration,
                                        const std::string& generated_by) {
  const RegressionModel& model = calibration.fit.model;
  const std::vector<std::pair<int, int>> terms = regression_terms(model.order());
  const std::vector<double> raw = model.raw_coefficients();
  nlohmann::ordered_json json;
  json["generated_by"] = generated_by;
  json["kind"] = "flange-calibration";
  json["format_version"] = 1;
  json["database"] = {{"path", calibration.database},
                      {"rows", calibration.rows},
                      {"rows_without_reference", calibration.rows_without_reference},
                      {"runs", calibration.runs}};
  json["order"] = model.order();
  json["scaling"] = {{"v_center", model.scaling().v_center},
                     {"v_half", model.scaling().v_half},
                     {"t_center", model.scaling().t_center},
                     {"t_half", model.scaling().t_half}};
  nlohmann::ordered_json coefficients = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < terms.size(); ++k) {
    coefficients.push_back({{"v_power", terms[k].first},
                            {"t_power", terms[k].second},
                            {"scaled", model.scaled_coefficients()(static_cast<Eigen::Index>(k))},
                            {"a", raw[k]}});
  }
  json["coefficients"] = coefficients;
  json["calibrated_range"] = {{"voltage_v", {calibration.range.v_min, calibration.range.v_max}},
                              {"temp_c", {calibration.range.t_min, calibration.range.t_max}},
                              {"clearance_mm", {calibration.range.d_min, calibration.range.d_max}}};
  auto stats_json = [](const FitStatistics& s) {
    return nlohmann::ordered_json{{"r", s.r},
                                  {"adjusted_r2", s.adjusted_r2},
                                  {"rmse_mm", s.rmse_mm},
                                  {"mae_mm", s.mae_mm},
                                  {"heldout_mae_mm", s.heldout_mae_mm},
                                  {"heldout_rmse_mm", s.heldout_rmse_mm}};
  };
  json["stats"] = stats_json(calibration.fit.stats);
  json["selection"] = calibration.fit.selection;
  nlohmann::ordered_json orders = nlohmann::ordered_json::array();
  for (const OrderCandidate& c : calibration.fit.candidates) {
    nlohmann::ordered_json entry{{"order", c.order}, {"terms", c.terms}};
    entry["stats"] = stats_json(c.stats);
    orders.push_back(entry);
  }
  json["orders_tried"] = orders;
  return json;
}

namespace {

double number_field(const nlohmann::json& json, const std::string& path, const char* key,
                    const std::string& where) {
  if (!json.contains(key) || !json[key].is_number()) {
    throw InputError(fmt::format("{}: field {}{} is missing or not a number", path, where, key));
  }
  const double value = json[key].get<double>();
  if (!std::isfinite(value)) {
    throw InputError(fmt::format("{}: field {}{} is not finite", path, where, key));
  }
  return value;
}

}  // namespace

namespace {

Calibration calibration_from_json(const nlohmann::json& json, const std::string& path);

}  // namespace

Calibration load_calibration(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw InputError(fmt::format("{}: cannot open the calibration", path));
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(file);
  } catch (const nlohmann::json::exception& error) {  // a syntax error or a number overflow
    throw InputError(fmt::format("{}: not valid JSON ({})", path, error.what()));
  }
  try {
    return calibration_from_json(json, path);
  } catch (const nlohmann::json::exception& error) {
    // A field of the wrong type that no check below names (e.g. an object where a number goes).
    throw InputError(fmt::format("{}: a field has the wrong type ({})", path, error.what()));
  }
}

namespace {

Calibration calibration_from_json(const nlohmann::json& json, const std::string& path) {
  if (!json.is_object() || !json.contains("kind") || json["kind"] != "flange-calibration") {
    throw InputError(fmt::format(
        "{}: field kind must be \"flange-calibration\" (make one with flange calibrate)", path));
  }
  const double order_value = number_field(json, path, "order", "");
  if (order_value < kMinRegressionOrder || order_value > kMaxRegressionOrder ||
      order_value != std::floor(order_value)) {
    throw InputError(fmt::format("{}: field order is {}; valid range is {} to {}", path,
                                 order_value, kMinRegressionOrder, kMaxRegressionOrder));
  }
  const int order = static_cast<int>(order_value);
  if (!json.contains("scaling") || !json["scaling"].is_object()) {
    throw InputError(fmt::format("{}: field scaling is missing", path));
  }
  VariableScaling scaling;
  scaling.v_center = number_field(json["scaling"], path, "v_center", "scaling.");
  scaling.v_half = number_field(json["scaling"], path, "v_half", "scaling.");
  scaling.t_center = number_field(json["scaling"], path, "t_center", "scaling.");
  scaling.t_half = number_field(json["scaling"], path, "t_half", "scaling.");
  if (scaling.v_half <= 0.0 || scaling.t_half <= 0.0) {
    throw InputError(fmt::format("{}: fields scaling.v_half and scaling.t_half must be > 0", path));
  }
  const std::vector<std::pair<int, int>> terms = regression_terms(order);
  if (!json.contains("coefficients") || !json["coefficients"].is_array() ||
      json["coefficients"].size() != terms.size()) {
    throw InputError(fmt::format("{}: field coefficients must list {} terms for order {}", path,
                                 terms.size(), order));
  }
  Eigen::VectorXd scaled(static_cast<Eigen::Index>(terms.size()));
  for (std::size_t k = 0; k < terms.size(); ++k) {
    const nlohmann::json& entry = json["coefficients"][k];
    const std::string where = fmt::format("coefficients[{}].", k);
    if (number_field(entry, path, "v_power", where) != terms[k].first ||
        number_field(entry, path, "t_power", where) != terms[k].second) {
      throw InputError(fmt::format("{}: field {}v_power/t_power must be {}/{} for order {}", path,
                                   where, terms[k].first, terms[k].second, order));
    }
    scaled(static_cast<Eigen::Index>(k)) = number_field(entry, path, "scaled", where);
  }
  Calibration calibration;
  calibration.fit.model = RegressionModel(order, scaling, scaled);
  if (!json.contains("calibrated_range")) {
    throw InputError(fmt::format("{}: field calibrated_range is missing", path));
  }
  auto pair_of = [&](const char* key) {
    const nlohmann::json& range = json["calibrated_range"];
    if (!range.contains(key) || !range[key].is_array() || range[key].size() != 2 ||
        !range[key][0].is_number() || !range[key][1].is_number()) {
      throw InputError(fmt::format("{}: field calibrated_range.{} must be [min, max]", path, key));
    }
    return std::make_pair(range[key][0].get<double>(), range[key][1].get<double>());
  };
  std::tie(calibration.range.v_min, calibration.range.v_max) = pair_of("voltage_v");
  std::tie(calibration.range.t_min, calibration.range.t_max) = pair_of("temp_c");
  std::tie(calibration.range.d_min, calibration.range.d_max) = pair_of("clearance_mm");
  calibration.database = json.value("/database/path"_json_pointer, std::string());
  return calibration;
}

}  // namespace

double eq_3_14(double v, double t) {
  return 1.16 + 0.3672 * v - 0.0036 * t + 0.05812 * v * v + 0.0006618 * v * t;
}

}  // namespace flange::host
