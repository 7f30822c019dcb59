// SPDX-License-Identifier: MIT
// The twin's parameters as JSON: the nominal polynomial, the noise and the switched-on effects
// with every parameter (docs/sensor_twin.md, "Twin file").
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "sensor_twin.h"

namespace flange::sim {

inline constexpr const char* kTwinFormat = "flange-sensor-twin/1";

// Fields in a fixed order (format, nominal, noise, effects; parameters as the effect declares
// them), so that saved files read well and diff cleanly.
nlohmann::ordered_json twin_to_json(const TwinConfig& config);

// Reads a twin from JSON. Missing sections take their defaults (thesis eq. 3.14, Table 4-1
// noise, no effects); unknown fields are errors. Throws BadArgument with one line starting
// with `where` (the file name) and naming the field, e.g. "twin.json: effects[1].params: ...".
TwinConfig twin_from_json(const nlohmann::json& json, const std::string& where);

// File forms of the above. Reading throws BadArgument for a missing file or invalid JSON
// (naming line and column); writing throws std::runtime_error when the file cannot be written.
TwinConfig load_twin(const std::filesystem::path& path);

// The nominal model from a calibration written by `flange calibrate` (model.json: its
// "coefficients" list of {v_power, t_power, a}), so that the twin inverts what was fitted on a
// bench. Throws BadArgument naming the file and field.
PolynomialSensorModel nominal_from_calibration(const std::filesystem::path& path);
void save_twin(const TwinConfig& config, const std::filesystem::path& path);

// The twin file (or the default twin), with the nominal model of a calibration if given, and the
// command line's effects (NAME or NAME:key=value,...) added or, when the file has them, retuned:
// the given keys change, the others keep their values. Throws BadArgument naming the effect.
TwinConfig twin_with_effects(const std::optional<std::filesystem::path>& twin_file,
                             const std::optional<std::filesystem::path>& calibration,
                             const std::vector<std::string>& effects);

}  // namespace flange::sim
