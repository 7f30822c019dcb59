// SPDX-License-Identifier: MIT
// Issue 12's precision aim as a test: every Butterworth SOS set the generator makes, orders 1 to 12
// at fc/fs from 0.001 to 0.4, keeps the bit-accurate core within 8 dB of the output-rounding floor
// (6.02 D + 1.76 dB at -1 dBFS, 97.1 dB for 16-bit samples) on a passband sine at fc/4, measured
// against the float design. docs/benchmarks_core.md has the table (bench/core_bench prints it).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

#include "fidelity.h"
#include "filter_json.h"
#include "generator.h"
#include "iir_core.h"
#include "reference_filter.h"

namespace {

using flange::coeffs::DesignRecord;
using flange::coeffs::DesignRequest;

constexpr double kLevelDbfs = -1.0;
constexpr double kAimBelowFloorDb = 8.0;

struct Measured {
  double snr_db = 0.0;
  double floor_db = 0.0;
};

Measured passband_snr(int order, double fc_over_fs) {
  DesignRequest request;
  request.name = "grid";
  request.fs_hz = 1.0;
  request.order = order;
  request.fc_hz = fc_over_fs;
  const DesignRecord record = flange::coeffs::generate_design(request, "precision_grid_test");
  EXPECT_TRUE(record.analysis.rejection.empty()) << record.analysis.rejection;
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() /
      ("flange_precision_grid_" + std::to_string(order) + "_" + std::to_string(fc_over_fs));
  flange::coeffs::write_design(record, dir, false);
  const flange::model::CoreConfig config = flange::model::load_core_config(dir / "filter.json");
  const flange::model::FloatDesign design = flange::model::load_float_design(dir / "filter.json");
  std::filesystem::remove_all(dir);

  flange::model::IirCore core(config);
  flange::model::ReferenceFilter reference(design);
  const double full_scale = std::ldexp(1.0, config.sample_width - 1);
  const double amplitude = std::pow(10.0, kLevelDbfs / 20.0) * (full_scale - 1.0);
  const double f = fc_over_fs / 4.0;
  // Settled: several time constants of the slowest pole and whole periods of the sine after it.
  const auto settle = static_cast<std::size_t>(std::max(15000.0, 10.0 / fc_over_fs));
  const auto span = static_cast<std::size_t>(std::max(25000.0, 8.0 / f));
  std::vector<double> want, got;
  for (std::size_t n = 0; n < settle + span; ++n) {
    const double x = std::round(amplitude * std::sin(2.0 * std::numbers::pi * f * static_cast<double>(n)));
    const double y_reference = reference.step(x / full_scale);
    const double y_core = core.step(static_cast<std::int32_t>(x)).sample * design.leftover_gain / full_scale;
    if (n < settle) continue;
    want.push_back(y_reference);
    got.push_back(y_core);
  }
  return {flange::model::snr_db(want, got), 6.02 * config.sample_width + 1.76 + kLevelDbfs};
}

class PrecisionGrid : public ::testing::TestWithParam<double> {};

TEST_P(PrecisionGrid, EveryOrderWithin8DbOfTheOutputRoundingFloor) {
  const double fc_over_fs = GetParam();
  std::string row = "fc/fs " + std::to_string(fc_over_fs) + ", orders 1-12, SNR dB:";
  for (int order = 1; order <= 12; ++order) {
    const Measured m = passband_snr(order, fc_over_fs);
    row += fmt::format(" {:.1f}", m.snr_db);
    EXPECT_GE(m.snr_db, m.floor_db - kAimBelowFloorDb)
        << "order " << order << ", fc/fs " << fc_over_fs << ": SNR " << m.snr_db
        << " dB against the floor " << m.floor_db << " dB";
  }
  std::cout << row << "\n";
}

INSTANTIATE_TEST_SUITE_P(CutOffs, PrecisionGrid,
                         ::testing::Values(0.001, 0.0026, 0.01, 0.05, 0.1, 0.2, 0.3, 0.4),
                         [](const ::testing::TestParamInfo<double>& cut_off) {
                           std::string name = "fc_over_fs_" + std::to_string(cut_off.param);
                           for (char& c : name) {
                             if (c == '.') c = '_';
                           }
                           return name;
                         });

}  // namespace
