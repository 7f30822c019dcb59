// SPDX-License-Identifier: MIT
#include "diagnose_command.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <ostream>

#include "cli.h"
#include "diagnose_report.h"
#include "input_error.h"
#include "recording_csv.h"
#include "sim_error.h"
#include "twin_file.h"

namespace flange::host {

CLI::App* add_diagnose_command(CLI::App& app, DiagnoseCommandOptions& options) {
  CLI::App* cmd = app.add_subcommand(
      "diagnose",
      "Where the sim-to-real gap of a recording lies, which effect causes it, and how "
      "far it shrinks on held-out data");
  cmd->add_option("--real", options.real, "recording (CSV t_s,clearance_mm,temp_c,voltage_v)");
  CLI::Option* holdout =
      cmd->add_option("--holdout", options.holdout, "a separate held-out recording");
  cmd->add_option("--holdout-fraction", options.holdout_fraction,
                  "hold out the last fraction of --real instead, 0.05 to 0.5")
      ->excludes(holdout)
      ->check(CLI::Range(0.05, 0.5));
  cmd->add_option("--twin", options.twin, "twin file (JSON); default: thesis eq. 3.14");
  cmd->add_option("--out", options.out, "folder for diagnosis.json and report.html");
  cmd->add_option("--seed", options.seed, "seed of the bootstrap resampling")->default_val(1);
  cmd->add_option("--bootstrap", options.bootstrap_rounds, "bootstrap rounds, 20 to 2000")
      ->default_val(100)
      ->check(CLI::Range(20, 2000));
  return cmd;
}

RecordingSeries read_recording_series(const std::string& path) {
  RecordingReader reader(path);
  RecordingSeries series;
  series.path = path;
  while (const std::optional<RecordingRow> row = reader.next()) {
    if (!row->clearance_mm) {
      throw InputError(fmt::format(
          "{}:{}: clearance_mm: empty; diagnose needs the reference clearance on every row (a "
          "number in mm)",
          path, row->line));
    }
    if (!series.t_s.empty() && row->t_s <= series.t_s.back()) {
      throw InputError(
          fmt::format("{}:{}: t_s: {} does not increase (a run column's restart "
                      "cannot be diagnosed as one series)",
                      path, row->line, row->t_s));
    }
    series.t_s.push_back(row->t_s);
    series.clearance_mm.push_back(*row->clearance_mm);
    series.temp_c.push_back(row->temp_c);
    series.voltage_v.push_back(row->voltage_v);
  }
  return series;
}

namespace {

RecordingSeries slice(const RecordingSeries& s, std::size_t begin, std::size_t end,
                      const std::string& label) {
  RecordingSeries part;
  part.path = label;
  const auto cut = [&](const std::vector<double>& v) {
    return std::vector<double>(v.begin() + static_cast<long>(begin),
                               v.begin() + static_cast<long>(end));
  };
  part.t_s = cut(s.t_s);
  part.clearance_mm = cut(s.clearance_mm);
  part.temp_c = cut(s.temp_c);
  part.voltage_v = cut(s.voltage_v);
  return part;
}

}  // namespace

int run_diagnose_command(const DiagnoseCommandOptions& options, std::ostream& out,
                         std::ostream& err) {
  try {
    if (options.real.empty())
      throw InputError(
          "--real: a recording is required (or --hw --coeffs DIR/filter.json for the float design "
          "against the RTL)");
    if (options.out.empty()) throw InputError("--out: an output folder is required");
    if (!options.holdout && !options.holdout_fraction) {
      throw InputError("give --holdout B.csv or --holdout-fraction F (0.05 to 0.5)");
    }
    DiagnoseOptions diagnose_options;
    if (options.twin) diagnose_options.twin = sim::load_twin(*options.twin);
    diagnose_options.seed = options.seed;
    diagnose_options.bootstrap_rounds = options.bootstrap_rounds;

    const RecordingSeries real = read_recording_series(options.real);
    RecordingSeries calibration, heldout;
    std::string heldout_name;
    if (options.holdout) {
      calibration = real;
      heldout = read_recording_series(*options.holdout);
      heldout_name = *options.holdout;
    } else {
      const double fraction = *options.holdout_fraction;
      const auto held =
          static_cast<std::size_t>(std::floor(fraction * static_cast<double>(real.size())));
      constexpr std::size_t kMinPart = 256;
      if (held < kMinPart || real.size() - held < kMinPart) {
        throw InputError(fmt::format(
            "{}: {} rows are too short to hold out {}: each part needs at least {} rows (the "
            "recording needs at least {} rows at this fraction)",
            options.real, real.size(), fraction, kMinPart,
            static_cast<std::size_t>(std::ceil(kMinPart / std::min(fraction, 1.0 - fraction)))));
      }
      calibration = slice(real, 0, real.size() - held, options.real + " (calibration part)");
      heldout = slice(real, real.size() - held, real.size(), options.real + " (held-out part)");
      heldout_name = fmt::format("last {} of {}", fraction, options.real);
    }
    const DiagnosisResult result = diagnose_in_detail(calibration, heldout, diagnose_options);

    std::filesystem::create_directories(options.out);
    const std::filesystem::path json_path = std::filesystem::path(options.out) / "diagnosis.json";
    std::ofstream json(json_path, std::ios::binary);
    json << diagnosis_json(result, options.real, heldout_name).dump(2) << "\n";
    json.close();
    if (!json) {
      err << "flange diagnose: " << json_path.string() << ": cannot write\n";
      return kExitFailure;
    }
    write_diagnosis_report(options.out, result, options.real);
    out << diagnosis_summary(result);
    out << "  wrote " << json_path.string() << " and "
        << (std::filesystem::path(options.out) / "report.html").string() << "\n";
    return kExitOk;
  } catch (const InputError& error) {
    err << "flange diagnose: " << error.what() << "\n";
    return kExitBadArgument;
  } catch (const sim::BadArgument& error) {
    err << "flange diagnose: " << error.what() << "\n";
    return kExitBadArgument;
  }
}

}  // namespace flange::host
