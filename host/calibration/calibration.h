// SPDX-License-Identifier: MIT
// A calibration: the fitted regression, the database it came from and the ranges it is valid
// in; stored as model.json. The database is a recording-format CSV that grows as sessions are
// appended (the thesis's self-updating agent refits on every addition).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "recording_row.h"
#include "regression.h"

namespace flange::host {

struct CalibratedRange {
  double v_min = 0.0, v_max = 0.0;
  double t_min = 0.0, t_max = 0.0;
  double d_min = 0.0, d_max = 0.0;
};

struct Calibration {
  RegressionFit fit;
  CalibratedRange range;
  std::string database;                    // path of the CSV it was fitted on
  std::size_t rows = 0;                    // data rows in the database
  std::size_t rows_without_reference = 0;  // rows with an empty clearance_mm (not fitted)
  std::vector<std::string> runs;           // distinct run labels, in order of appearance

  struct Estimate {
    double clearance_mm = 0.0;
    bool outside_calibration = false;  // V or T outside the calibrated range: extrapolated
  };
  Estimate estimate(double voltage_v, double temp_c) const;
};

// Reads the database (strict: any bad row is an InputError) and fits it.
Calibration calibrate_database(const std::string& database_csv, const RegressionOptions& options);

// The same fit from rows already read (a store's bench sessions, in the order they were
// recorded): `source` names them in messages and in the calibration's database field.
Calibration calibrate_rows(const std::string& source, const std::vector<RecordingRow>& rows,
                           const RegressionOptions& options);

// Validates `new_csv` and appends its rows to `database_csv` (creating the run column if the
// database has none; rows of a file without one are labelled with the file's stem). The
// combined file is checked before it replaces the database, so a failed append changes nothing.
std::size_t append_to_database(const std::string& database_csv, const std::string& new_csv);

nlohmann::ordered_json calibration_json(const Calibration& calibration,
                                        const std::string& generated_by);
// Throws InputError naming the file and the field that is missing or out of range.
Calibration load_calibration(const std::string& path);

// The thesis's fixed regression, eq. 3.14: clearance in mm from the sensor voltage (V) and the
// temperature (deg C); what the host uses when no calibration is given.
double eq_3_14(double v, double t);

}  // namespace flange::host
