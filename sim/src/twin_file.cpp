// SPDX-License-Identifier: MIT
#include "twin_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "effect_argument.h"
#include "effect_catalogue.h"
#include "sim_error.h"

namespace flange::sim {
namespace {

using nlohmann::json;

void reject_unknown_fields(const json& object, const std::set<std::string>& known,
                           const std::string& where) {
  for (const auto& item : object.items()) {
    if (known.count(item.key()) == 0) {
      std::string names;
      for (const std::string& name : known) names += (names.empty() ? "" : ", ") + name;
      throw BadArgument(
          fmt::format("{}: unknown field '{}'; expected one of: {}", where, item.key(), names));
    }
  }
}

const json& require_object(const json& value, const std::string& where) {
  if (!value.is_object()) throw BadArgument(fmt::format("{}: expected a JSON object", where));
  return value;
}

double require_number(const json& value, const std::string& where) {
  if (!value.is_number()) throw BadArgument(fmt::format("{}: expected a number", where));
  return value.get<double>();
}

PolynomialSensorModel nominal_from_json(const json& nominal, const std::string& where) {
  require_object(nominal, where);
  reject_unknown_fields(nominal, {"model", "a", "voltage_range_v"}, where);
  if (!nominal.contains("a") || !nominal["a"].is_array() || nominal["a"].empty()) {
    throw BadArgument(
        fmt::format("{}.a: expected rows of coefficients, a[i][j] multiplying V^i T^j", where));
  }
  const json& rows = nominal["a"];
  const std::size_t columns = rows[0].is_array() ? rows[0].size() : 0;
  Eigen::MatrixXd a(static_cast<Eigen::Index>(rows.size()), static_cast<Eigen::Index>(columns));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::string row_where = fmt::format("{}.a[{}]", where, i);
    if (!rows[i].is_array() || rows[i].size() != columns || columns == 0) {
      throw BadArgument(fmt::format("{}: expected a row of {} numbers (all rows alike)", row_where,
                                    std::max<std::size_t>(columns, 1)));
    }
    for (std::size_t j = 0; j < columns; ++j) {
      a(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) =
          require_number(rows[i][j], fmt::format("{}[{}]", row_where, j));
    }
  }
  double v_min_v = 0.0;
  double v_max_v = 10.0;
  if (nominal.contains("voltage_range_v")) {
    const json& range = nominal["voltage_range_v"];
    if (!range.is_array() || range.size() != 2) {
      throw BadArgument(fmt::format("{}.voltage_range_v: expected [min, max] in volts", where));
    }
    v_min_v = require_number(range[0], where + ".voltage_range_v[0]");
    v_max_v = require_number(range[1], where + ".voltage_range_v[1]");
  }
  try {
    return PolynomialSensorModel(a, v_min_v, v_max_v);
  } catch (const BadArgument& error) {
    throw BadArgument(fmt::format("{}: {}", where, error.what()));
  }
}

std::vector<double> numbers_of(const json& value, const std::string& where) {
  if (!value.is_array()) throw BadArgument(fmt::format("{}: expected an array of numbers", where));
  std::vector<double> out;
  for (std::size_t k = 0; k < value.size(); ++k) {
    out.push_back(require_number(value[k], fmt::format("{}[{}]", where, k)));
  }
  return out;
}

// The tabulated effect's table (effect_table.h): its fields as the struct names them.
std::shared_ptr<const EffectTable> table_from_json(const json& value, const std::string& where) {
  require_object(value, where);
  reject_unknown_fields(
      value, {"clearance_mm", "temperature_c", "added_v", "age_days", "age_added_v"}, where);
  for (const char* field : {"clearance_mm", "temperature_c", "added_v"}) {
    if (!value.contains(field)) throw BadArgument(fmt::format("{}.{}: missing", where, field));
  }
  auto table = std::make_shared<EffectTable>();
  table->clearance_mm = numbers_of(value["clearance_mm"], where + ".clearance_mm");
  table->temperature_c = numbers_of(value["temperature_c"], where + ".temperature_c");
  const json& rows = value["added_v"];
  if (!rows.is_array())
    throw BadArgument(fmt::format("{}.added_v: expected rows of numbers", where));
  for (std::size_t i = 0; i < rows.size(); ++i) {
    table->added_v.push_back(numbers_of(rows[i], fmt::format("{}.added_v[{}]", where, i)));
  }
  if (value.contains("age_days"))
    table->age_days = numbers_of(value["age_days"], where + ".age_days");
  if (value.contains("age_added_v")) {
    table->age_added_v = numbers_of(value["age_added_v"], where + ".age_added_v");
  }
  if (const std::string problem = table_problem(*table); !problem.empty()) {
    throw BadArgument(fmt::format("{}.{}", where, problem));
  }
  return table;
}

nlohmann::ordered_json table_to_json(const EffectTable& table) {
  nlohmann::ordered_json out = {{"clearance_mm", table.clearance_mm},
                                {"temperature_c", table.temperature_c},
                                {"added_v", table.added_v}};
  if (!table.age_days.empty()) {
    out["age_days"] = table.age_days;
    out["age_added_v"] = table.age_added_v;
  }
  return out;
}

// An effect's "fitted_over": {"clearance_mm": [low, high], "temperature_c": [low, high]}.
FittedRanges fitted_ranges_from_json(const json& value, const std::string& where) {
  require_object(value, where);
  reject_unknown_fields(value, {"clearance_mm", "temperature_c"}, where);
  const auto pair_of = [&](const char* field) {
    if (!value.contains(field)) throw BadArgument(fmt::format("{}.{}: missing", where, field));
    const std::vector<double> pair = numbers_of(value[field], fmt::format("{}.{}", where, field));
    if (pair.size() != 2) {
      throw BadArgument(fmt::format("{}.{}: expected [low, high]", where, field));
    }
    return pair;
  };
  const std::vector<double> clearance = pair_of("clearance_mm");
  const std::vector<double> temperature = pair_of("temperature_c");
  const FittedRanges ranges{clearance[0], clearance[1], temperature[0], temperature[1]};
  if (const std::string problem = fitted_ranges_problem(ranges); !problem.empty()) {
    throw BadArgument(fmt::format("{}.{}", where, problem));
  }
  return ranges;
}

}  // namespace

nlohmann::ordered_json twin_to_json(const TwinConfig& config) {
  using OrderedJson = nlohmann::ordered_json;
  OrderedJson a = OrderedJson::array();
  const Eigen::MatrixXd& coefficients = config.nominal.coefficients();
  for (Eigen::Index i = 0; i < coefficients.rows(); ++i) {
    OrderedJson row = OrderedJson::array();
    for (Eigen::Index j = 0; j < coefficients.cols(); ++j) row.push_back(coefficients(i, j));
    a.push_back(row);
  }
  OrderedJson effects = OrderedJson::array();
  std::vector<const EffectSettings*> in_chain_order;
  for (const EffectSettings& effect : config.effects) in_chain_order.push_back(&effect);
  std::sort(in_chain_order.begin(), in_chain_order.end(),
            [](const EffectSettings* x, const EffectSettings* y) {
              return catalogue_index(x->name) < catalogue_index(y->name);
            });
  for (const EffectSettings* effect : in_chain_order) {
    OrderedJson params = OrderedJson::object();
    const EffectSpec& spec = effect_catalogue()[catalogue_index(effect->name)];
    for (const ParamSpec& param : spec.params) params[param.key] = effect->params.at(param.key);
    OrderedJson entry = {{"name", effect->name}, {"params", params}};
    if (effect->table) entry["table"] = table_to_json(*effect->table);
    if (const std::optional<FittedRanges>& r = effect->fitted_over) {
      entry["fitted_over"] = {{"clearance_mm", {r->clearance_lo_mm, r->clearance_hi_mm}},
                              {"temperature_c", {r->temperature_lo_c, r->temperature_hi_c}}};
    }
    effects.push_back(entry);
  }
  OrderedJson root = {
      {"format", kTwinFormat},
      {"nominal",
       {{"model", "d_mm = sum over i, j of a[i][j] * V^i * T^j (V in volts, T in degC)"},
        {"a", a},
        {"voltage_range_v", {config.nominal.v_min_v(), config.nominal.v_max_v()}}}},
      {"noise",
       {{"voltage_std_v", config.noise.voltage_std_v},
        {"temperature_std_c", config.noise.temperature_std_c}}},
      {"effects", effects},
  };
  if (config.noise.rounding_lsb_v > 0.0) {
    root["noise"]["rounding_lsb_v"] = config.noise.rounding_lsb_v;
  }
  if (!config.notes.empty()) root["notes"] = config.notes;
  return root;
}

TwinConfig twin_from_json(const json& root, const std::string& where) {
  require_object(root, where);
  reject_unknown_fields(root, {"format", "nominal", "noise", "effects", "notes"}, where);
  if (root.contains("format") && root["format"] != kTwinFormat) {
    throw BadArgument(fmt::format("{}: format: expected \"{}\"", where, kTwinFormat));
  }
  TwinConfig config;
  if (root.contains("nominal"))
    config.nominal = nominal_from_json(root["nominal"], where + ": nominal");
  if (root.contains("noise")) {
    const std::string noise_where = where + ": noise";
    const json& noise = require_object(root["noise"], noise_where);
    reject_unknown_fields(noise, {"voltage_std_v", "temperature_std_c", "rounding_lsb_v"},
                          noise_where);
    if (noise.contains("voltage_std_v")) {
      config.noise.voltage_std_v =
          require_number(noise["voltage_std_v"], noise_where + ".voltage_std_v");
    }
    if (noise.contains("temperature_std_c")) {
      config.noise.temperature_std_c =
          require_number(noise["temperature_std_c"], noise_where + ".temperature_std_c");
    }
    if (noise.contains("rounding_lsb_v")) {
      config.noise.rounding_lsb_v =
          require_number(noise["rounding_lsb_v"], noise_where + ".rounding_lsb_v");
    }
  }
  if (root.contains("effects")) {
    const json& effects = root["effects"];
    if (!effects.is_array())
      throw BadArgument(fmt::format("{}: effects: expected an array", where));
    for (std::size_t k = 0; k < effects.size(); ++k) {
      const std::string effect_where = fmt::format("{}: effects[{}]", where, k);
      const json& effect = require_object(effects[k], effect_where);
      reject_unknown_fields(effect, {"name", "params", "table", "fitted_over"}, effect_where);
      if (!effect.contains("name") || !effect["name"].is_string()) {
        throw BadArgument(fmt::format("{}.name: expected the effect's name", effect_where));
      }
      ParamValues values;
      if (effect.contains("params")) {
        const json& params = require_object(effect["params"], effect_where + ".params");
        for (const auto& item : params.items()) {
          values[item.key()] =
              require_number(item.value(), fmt::format("{}.params.{}", effect_where, item.key()));
        }
      }
      EffectSettings settings =
          make_effect_settings(effect["name"].get<std::string>(), values, effect_where);
      const bool needs_table = settings.name == tabulated_effect_name();
      if (effect.contains("table") != needs_table) {
        throw BadArgument(effect_where + (needs_table
                                              ? ".table: the tabulated effect needs its table"
                                              : ".table: only the tabulated effect has one"));
      }
      if (needs_table) settings.table = table_from_json(effect["table"], effect_where + ".table");
      if (effect.contains("fitted_over")) {
        settings.fitted_over =
            fitted_ranges_from_json(effect["fitted_over"], effect_where + ".fitted_over");
      }
      config.effects.push_back(std::move(settings));
    }
  }
  if (root.contains("notes")) {
    const json& notes = root["notes"];
    if (!notes.is_array())
      throw BadArgument(fmt::format("{}: notes: expected an array of strings", where));
    for (std::size_t k = 0; k < notes.size(); ++k) {
      if (!notes[k].is_string()) {
        throw BadArgument(fmt::format("{}: notes[{}]: expected a string", where, k));
      }
      config.notes.push_back(notes[k].get<std::string>());
    }
  }
  try {
    check_twin_config(config);
  } catch (const BadArgument& error) {
    throw BadArgument(fmt::format("{}: {}", where, error.what()));
  }
  return config;
}

static TwinConfig load_twin_unguarded(const std::filesystem::path& path) {
  const std::string where = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw BadArgument(fmt::format("{}: cannot open the twin file", where));
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  json root;
  try {
    root = json::parse(text);
  } catch (const json::parse_error& error) {
    // nlohmann reports a byte offset; people read lines and columns.
    std::size_t line = 1;
    std::size_t column = 1;
    const std::size_t end =
        std::min<std::size_t>(error.byte == 0 ? 0 : error.byte - 1, text.size());
    for (std::size_t k = 0; k < end; ++k) {
      if (text[k] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    throw BadArgument(fmt::format("{}: line {}, column {}: not valid JSON", where, line, column));
  }
  return twin_from_json(root, where);
}

TwinConfig load_twin(const std::filesystem::path& path) {
  // A field of the wrong type that no check names (an object where a number goes, ...) is
  // refused like any other bad field, never let through as a library exception.
  try {
    return load_twin_unguarded(path);
  } catch (const nlohmann::json::exception& error) {
    throw BadArgument(
        fmt::format("{}: a field has the wrong type ({})", path.string(), error.what()));
  }
}

void save_twin(const TwinConfig& config, const std::filesystem::path& path) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error(fmt::format("{}: cannot write the twin file", path.string()));
  out << twin_to_json(config).dump(2) << "\n";
  if (!out)
    throw std::runtime_error(fmt::format("{}: writing the twin file failed", path.string()));
}

static PolynomialSensorModel nominal_from_calibration_unguarded(const std::filesystem::path& path) {
  const std::string where = path.string();
  std::ifstream file(path);
  if (!file) throw BadArgument(where + ": cannot open the calibration");
  json calibration;
  try {
    calibration = json::parse(file);
  } catch (const json::parse_error& error) {
    throw BadArgument(fmt::format("{}: not valid JSON ({})", where, error.what()));
  }
  if (!calibration.is_object() || calibration.value("kind", "") != "flange-calibration") {
    throw BadArgument(where + ": field kind must be \"flange-calibration\" (flange calibrate)");
  }
  if (!calibration.contains("coefficients") || !calibration["coefficients"].is_array() ||
      calibration["coefficients"].empty()) {
    throw BadArgument(where + ": field coefficients must list {v_power, t_power, a}");
  }
  int v_max = 0;
  int t_max = 0;
  std::vector<std::tuple<int, int, double>> terms;
  for (std::size_t k = 0; k < calibration["coefficients"].size(); ++k) {
    const json& term = calibration["coefficients"][k];
    const std::string term_where = fmt::format("{}: coefficients[{}]", where, k);
    require_object(term, term_where);
    const double v_power = require_number(term.value("v_power", json()), term_where + ".v_power");
    const double t_power = require_number(term.value("t_power", json()), term_where + ".t_power");
    const double a = require_number(term.value("a", json()), term_where + ".a");
    if (v_power < 0 || t_power < 0 || v_power > 12 || t_power > 12 ||
        v_power != static_cast<int>(v_power) || t_power != static_cast<int>(t_power)) {
      throw BadArgument(term_where + ": v_power and t_power must be whole numbers 0 to 12");
    }
    terms.emplace_back(static_cast<int>(v_power), static_cast<int>(t_power), a);
    v_max = std::max(v_max, static_cast<int>(v_power));
    t_max = std::max(t_max, static_cast<int>(t_power));
  }
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(v_max + 1, t_max + 1);
  for (const auto& [i, j, value] : terms) a(i, j) += value;
  try {
    return PolynomialSensorModel(a, 0.0, 10.0);
  } catch (const BadArgument& error) {
    throw BadArgument(fmt::format("{}: {}", where, error.what()));
  }
}

PolynomialSensorModel nominal_from_calibration(const std::filesystem::path& path) {
  // A field of the wrong type that no check names (an object where a number goes, ...) is
  // refused like any other bad field, never let through as a library exception.
  try {
    return nominal_from_calibration_unguarded(path);
  } catch (const nlohmann::json::exception& error) {
    throw BadArgument(
        fmt::format("{}: a field has the wrong type ({})", path.string(), error.what()));
  }
}

TwinConfig twin_with_effects(const std::optional<std::filesystem::path>& twin_file,
                             const std::optional<std::filesystem::path>& calibration,
                             const std::vector<std::string>& effects) {
  TwinConfig config = twin_file ? load_twin(*twin_file) : TwinConfig{};
  if (calibration) config.nominal = nominal_from_calibration(*calibration);
  std::vector<std::string> given;
  for (const std::string& text : effects) {
    const EffectArgument argument = parse_effect_argument(text);
    const std::string where = "--effect " + argument.name;
    for (const std::string& name : given) {
      if (name == argument.name) throw BadArgument(where + ": the effect is given twice");
    }
    given.push_back(argument.name);
    EffectSettings* existing = nullptr;
    for (EffectSettings& effect : config.effects) {
      if (effect.name == argument.name) existing = &effect;
    }
    if (existing != nullptr) {
      // On top of a twin file: the given keys retune the effect, the others keep their values.
      // The ranges it was fitted on stay only while its parameters are the fitted ones.
      ParamValues values = existing->params;
      for (const auto& [key, value] : argument.values) values[key] = value;
      std::shared_ptr<const EffectTable> table = existing->table;
      const std::optional<FittedRanges> fitted_over =
          values == existing->params ? existing->fitted_over : std::nullopt;
      *existing = make_effect_settings(argument.name, values, where);
      existing->table = std::move(table);
      existing->fitted_over = fitted_over;
    } else if (argument.name == tabulated_effect_name()) {
      throw BadArgument(where +
                        ": the tabulated effect needs its table, which only a twin file "
                        "gives (--twin)");
    } else {
      config.effects.push_back(make_effect_settings(argument.name, argument.values, where));
    }
  }
  return config;
}

}  // namespace flange::sim
