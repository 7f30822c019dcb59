// SPDX-License-Identifier: MIT
// The improved twin `flange diagnose` writes (twin.json): its table reproduces the free shapes, the
// twin file holds and replays it, and diagnosing a pair again against it finds nothing left on
// pairs of every class whose first verdict was "explained".
#include "improved_twin.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli.h"
#include "diagnose_selftest.h"
#include "diagnosis_detail.h"
#include "effect_classes.h"
#include "improved_twin_reasons.h"
#include "parallel_work.h"
#include "sensor_twin.h"
#include "sim_error.h"
#include "table_fit.h"
#include "test_files.h"
#include "twin_file.h"
#include "verdict_reasons.h"

namespace flange::diagnose {
namespace {

TEST(EffectTableFit, ReproducesASurfaceOfClearanceAndTemperatureAndACurveOfAge) {
  std::vector<double> d, t, age, added;
  for (int i = 0; i < 4000; ++i) {
    d.push_back(1.0 + 8.0 * std::fmod(i * 0.618034, 1.0));
    t.push_back(20.0 + 60.0 * std::fmod(i * 0.414214, 1.0));
    age.push_back(i / 4000.0);
    added.push_back(0.1 * std::sin(d.back()) + 0.002 * (t.back() - 20.0) + 0.05 * age.back());
  }
  const TableFit fit = fit_effect_table({{d, t, age, added}}, true);
  ASSERT_EQ(fit.misfit_rms_v.size(), 1u);
  EXPECT_LT(fit.misfit_rms_v[0], 2e-3);  // against a shape of about 0.1 V
  EXPECT_EQ(sim::table_problem(fit.table), "");
}

TEST(TabulatedEffect, TheTwinAddsWhatItsTableSaysAndTheTwinFileKeepsIt) {
  auto table = std::make_shared<sim::EffectTable>();
  table->clearance_mm = {0.0, 10.0};
  table->temperature_c = {0.0, 100.0};
  table->added_v = {{0.0, 0.5}, {1.0, 1.5}};
  sim::TwinConfig config;
  config.noise.voltage_std_v = 0.0;
  sim::TwinConfig with = config;
  sim::EffectSettings tabulated =
      sim::make_effect_settings(sim::tabulated_effect_name(), {}, "test");
  tabulated.table = table;
  with.effects.push_back(tabulated);
  const sim::TwinConfig read = sim::twin_from_json(sim::twin_to_json(with), "twin.json");
  ASSERT_EQ(read.effects.size(), 1u);
  EXPECT_EQ(read.effects[0], tabulated);
  sim::SensorTwin plain(config, 1), added(read, 1);
  const sim::TrueState truth{0.0, 5.0, 50.0};
  // Bilinear at the middle of the one cell: 0.75 V.
  EXPECT_NEAR(added.step(truth).voltage_v - plain.step(truth).voltage_v, 0.75, 1e-12);
}

TEST(TabulatedEffect, ATableIsRefusedWhereItDoesNotBelongOrIsMalformed) {
  const nlohmann::json without = {{"effects", {{{"name", "tabulated"}}}}};
  EXPECT_THROW(sim::twin_from_json(without, "twin.json"), sim::BadArgument);
  const nlohmann::json misplaced = {
      {"effects",
       {{{"name", "vibration"},
         {"table",
          {{"clearance_mm", {0, 1}}, {"temperature_c", {0, 1}}, {"added_v", {{0, 0}, {0, 0}}}}}}}}};
  EXPECT_THROW(sim::twin_from_json(misplaced, "twin.json"), sim::BadArgument);
  const nlohmann::json decreasing = {
      {"effects",
       {{{"name", "tabulated"},
         {"table",
          {{"clearance_mm", {1, 0}}, {"temperature_c", {0, 1}}, {"added_v", {{0, 0}, {0, 0}}}}}}}}};
  try {
    sim::twin_from_json(decreasing, "twin.json");
    FAIL() << "a decreasing axis was accepted";
  } catch (const sim::BadArgument& error) {
    EXPECT_NE(std::string(error.what()).find("effects[0].table.clearance_mm"), std::string::npos)
        << error.what();
  }
}

// Re-diagnosis: for every class the self-test draws, its first single-effect cases (short
// sessions) until one is explained.
constexpr double kDurationS = 1200;
constexpr std::uint64_t kSeed = 41;
constexpr std::size_t kCasesPerClass = 3;

std::vector<std::vector<SelftestCaseSpec>> first_cases_of_every_class() {
  std::map<std::string, std::vector<SelftestCaseSpec>> by_class;
  for (int index = 1; index < 400; ++index) {
    const SelftestCaseSpec spec = draw_selftest_case(index, kSeed);
    if (spec.kind != SelftestKind::kSingle) continue;
    std::vector<SelftestCaseSpec>& cases = by_class[spec.truth.front().name];
    if (cases.size() < kCasesPerClass) cases.push_back(spec);
  }
  std::vector<std::vector<SelftestCaseSpec>> classes;
  for (const auto& [name, cases] : by_class) classes.push_back(cases);
  return classes;
}

struct Rediagnosis {
  int index = 0;
  std::string truth, first, second;
  std::vector<std::string> held_as;  // how the improved twin holds each finding
  std::vector<std::string> found;    // the first diagnosis's findings
  sim::TwinConfig twin;              // the improved twin, as read back from its file
};

Rediagnosis rediagnose(const SelftestCaseSpec& spec) {
  const SelftestRecordings rec = make_selftest_recordings(spec, kDurationS);
  DiagnoseOptions options;
  options.bootstrap_rounds = 20;
  const DiagnosisResult first = diagnose_in_detail(rec.calibration, rec.heldout, options);
  Rediagnosis out{spec.index, spec.truth.front().name, status_text(first.diagnosis.status), "", {}, {}, {}};
  if (first.diagnosis.status != Status::kExplained) return out;
  for (const HeldFinding& f : first.improved_twin.findings) out.held_as.push_back(reasons::held_as_text(f.held_as));
  for (const EffectFinding& f : first.diagnosis.effects) out.found.push_back(f.name);
  // Through the twin file, as `flange diagnose --twin twin.json` reads it.
  options.twin = sim::twin_from_json(sim::twin_to_json(first.improved_twin.twin), "twin.json");
  out.twin = options.twin;
  out.second = status_text(diagnose_in_detail(rec.calibration, rec.heldout, options).diagnosis.status);
  return out;
}

// The first of `cases` whose first verdict is "explained", re-diagnosed; else the last tried.
Rediagnosis rediagnose_first_explained(const std::vector<SelftestCaseSpec>& cases) {
  Rediagnosis r;
  for (const SelftestCaseSpec& spec : cases) {
    r = rediagnose(spec);
    if (r.first == "explained") break;
  }
  return r;
}

TEST(ImprovedTwin, RediagnosingAnExplainedPairOfEveryClassAgainstItLeavesNone) {
  const std::vector<std::vector<SelftestCaseSpec>> classes = first_cases_of_every_class();
  ASSERT_EQ(classes.size(), 10u);
  std::vector<Rediagnosis> results(classes.size());
  run_in_parallel(static_cast<int>(classes.size()), 2, [&](int i) {
    results[static_cast<std::size_t>(i)] = rediagnose_first_explained(classes[i]);
  });
  for (const Rediagnosis& r : results) {
    std::cout << "case " << r.index << ", " << r.truth << ": " << r.first
              << (r.second.empty() ? "" : " -> " + r.second);
    for (const std::string& held : r.held_as) std::cout << " [" << held << "]";
    std::cout << "\n";
    // Every class has an explained pair among its first cases, and against its improved twin
    // (mount motion included: the stages' null replicas draw the motion the twin holds) the
    // same pair leaves nothing.
    EXPECT_EQ(r.first, "explained") << r.truth << ": none of its first " << kCasesPerClass
                                    << " cases was explained";
    if (r.first != "explained") continue;
    EXPECT_EQ(r.second, "none") << r.truth << " (reproduce: bash scripts/rediagnose_pairs.sh "
                                << "--reality twin --seed " << kSeed << " --from " << r.index
                                << " --to " << r.index << " --duration " << kDurationS << ")";
  }
}

// A recording whose gap is a bump in temperature that no library formula has: the free curve of
// temperature takes it, and the improved twin holds it as a table.
SelftestCaseSpec temperature_bump_case() {
  auto table = std::make_shared<sim::EffectTable>();
  table->clearance_mm = {0.0, 12.0};
  for (double t = 10.0; t <= 110.0; t += 2.0) table->temperature_c.push_back(t);
  for (int i = 0; i < 2; ++i) {
    std::vector<double> row;
    for (const double t : table->temperature_c)
      row.push_back(0.25 * std::exp(-std::pow((t - 60.0) / 12.0, 2)));
    table->added_v.push_back(row);
  }
  SelftestCaseSpec spec;
  spec.index = 1;
  spec.noise_seed = 5;
  sim::EffectSettings bump = sim::make_effect_settings(sim::tabulated_effect_name(), {}, "test");
  bump.table = table;
  spec.truth = {bump};
  return spec;
}

TEST(ImprovedTwin, AFreeShapeIsHeldAsATableAndRediagnosisLeavesNone) {
  const Rediagnosis r = rediagnose(temperature_bump_case());
  ASSERT_EQ(r.first, "explained");
  EXPECT_NE(std::find(r.held_as.begin(), r.held_as.end(), "table"), r.held_as.end());
  EXPECT_EQ(r.second, "none");
}

// A housing that lags in the heat and pulls the output by 0.03 V per degC of the ambient's lead
// over its 300 s lag: several times what the coil's dV/dT makes of a lag, so only the thermal
// lag's family in volts takes it. The improved twin holds it as thermal_lag_volts (the family's
// lags, weighed as fitted), and re-diagnosis against that twin leaves nothing.
TEST(ImprovedTwin, ALagInVoltsIsHeldAsTheTwinsVoltsLagAndRediagnosisLeavesNone) {
  SelftestCaseSpec spec;
  spec.index = 1;
  spec.noise_seed = 7;
  spec.truth = {sim::make_effect_settings("thermal_lag_volts",
                                          {{"v_per_c", 0.03}, {"tau_1_s", 300.0}}, "test")};
  const Rediagnosis r = rediagnose(spec);
  ASSERT_EQ(r.first, "explained");
  EXPECT_EQ(r.found, std::vector<std::string>{"thermal_lag"});
  const auto held = std::find_if(r.twin.effects.begin(), r.twin.effects.end(),
                                 [](const sim::EffectSettings& e) { return e.name == "thermal_lag_volts"; });
  ASSERT_NE(held, r.twin.effects.end()) << "the twin does not hold the lag in volts";
  EXPECT_NEAR(held->params.at("v_per_c"), 0.03, 0.006);
  EXPECT_EQ(r.held_as, std::vector<std::string>{"library effect and table"});
  EXPECT_EQ(r.second, "none");
}

TEST(ImprovedTwinCommand, DiagnoseWritesTwinJsonThatSimulateAndDiagnoseTake) {
  const auto dir = testing::fresh_test_dir("improved_twin_command");
  std::ostringstream out, err;
  // One self-test case writes its two sessions (its status says only whether the aims were met).
  cli::run_flange({"diagnose", "--selftest", "--case", "1", "--seed", "1", "--duration", "600",
                   "--bootstrap", "20", "--out", dir.string()},
                  out, err);
  const std::string real = (dir / "case_1_calibration.csv").string();
  ASSERT_TRUE(std::filesystem::exists(real)) << err.str();
  const std::string heldout = (dir / "case_1_heldout.csv").string();
  const auto first = dir / "first";
  ASSERT_EQ(cli::run_flange({"diagnose", "--real", real, "--holdout", heldout, "--bootstrap", "20",
                             "--out", first.string()},
                            out, err),
            0)
      << err.str();
  ASSERT_TRUE(std::filesystem::exists(first / "twin.json"));
  std::ifstream diagnosis_file(first / "diagnosis.json");
  const nlohmann::json diagnosis = nlohmann::json::parse(diagnosis_file);
  EXPECT_EQ(diagnosis["improved_twin"]["file"], "twin.json");
  const std::string twin = (first / "twin.json").string();
  EXPECT_EQ(cli::run_flange({"simulate", "--scenario", "bench", "--seed", "3", "--duration", "60",
                             "--twin", twin, "--out", (dir / "sim.csv").string()},
                            out, err),
            0)
      << err.str();
  EXPECT_EQ(cli::run_flange({"diagnose", "--real", real, "--holdout", heldout, "--twin", twin,
                             "--bootstrap", "20", "--out", (dir / "again").string()},
                            out, err),
            0)
      << err.str();
}

}  // namespace
}  // namespace flange::diagnose
