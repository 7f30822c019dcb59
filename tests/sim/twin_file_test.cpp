// SPDX-License-Identifier: MIT
// The twin file: what is saved loads back to the same twin, and bad files are named precisely.
#include "twin_file.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "sim_error.h"

namespace flange::sim {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::path(FLANGE_BINARY_DIR) / "test_twin_file";
  fs::create_directories(dir);
  return dir / name;
}

std::string load_error(const std::string& text) {
  const fs::path path = scratch("bad.json");
  std::ofstream(path) << text;
  try {
    load_twin(path);
  } catch (const BadArgument& error) {
    return error.what();
  }
  return "";
}

TwinConfig every_effect_retuned() {
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(4, 2);
  a << 1.2, -0.004, 0.35, 0.0007, 0.06, 0.0, 0.0008, 1e-7;
  TwinConfig config;
  config.nominal = PolynomialSensorModel(a, 0.0, 10.0);
  config.noise = {0.031, 0.25};
  // Listed backwards on purpose: the file keeps chain order.
  config.effects = {
      make_effect_settings("adc_quantization", {{"bits", 14}}, "t"),
      make_effect_settings("channel_skew", {{"skew_s", -0.4}}, "t"),
      make_effect_settings("mains_pickup", {{"mains_hz", 60}, {"phase_deg", 1.0 / 3.0}}, "t"),
      make_effect_settings("thermal_lag_volts", {{"v_per_c", -0.02}, {"weight_1", 0.75},
                                                 {"weight_2", 0.25}, {"tau_3_s", 1200}}, "t"),
      make_effect_settings("range_compression", {{"onset_c", 45}}, "t"),
      make_effect_settings("ageing_drift", {{"rate_v_per_day", 0.123456789012345}}, "t"),
      make_effect_settings("temp_offset_drift", {{"reference_c", 22}}, "t"),
      make_effect_settings("temp_gain_drift", {{"gain_per_c", -7e-4}}, "t"),
      make_effect_settings("nonlinearity", {{"bow_v", -0.02}}, "t"),
      make_effect_settings("thermal_lag", {{"tau_s", 45}}, "t"),
      make_effect_settings("vibration", {{"rms_mm", 0.02}}, "t"),
  };
  return config;
}

TEST(TwinFile, SaveThenLoadGivesTheSameTwin) {
  const TwinConfig original = every_effect_retuned();
  const fs::path path = scratch("round_trip.json");
  save_twin(original, path);
  const TwinConfig loaded = load_twin(path);

  EXPECT_EQ(loaded.nominal.coefficients(), original.nominal.coefficients());
  EXPECT_EQ(loaded.noise, original.noise);
  ASSERT_EQ(loaded.effects.size(), original.effects.size());
  for (const EffectSettings& effect : original.effects) {
    bool found = false;
    for (const EffectSettings& back : loaded.effects) found = found || back == effect;
    EXPECT_TRUE(found) << effect.name;
  }
  EXPECT_EQ(twin_to_json(loaded).dump(), twin_to_json(original).dump());
  // Saved in chain order.
  EXPECT_EQ(twin_to_json(loaded)["effects"][0]["name"], "vibration");

  SensorTwin a(original, 99);
  SensorTwin b(loaded, 99);
  for (int n = 0; n < 500; ++n) {
    const TrueState truth{n / 10.0, 2.0 + 0.015 * n, 20.0 + 0.15 * n};
    const Reading ra = a.step(truth);
    const Reading rb = b.step(truth);
    ASSERT_EQ(ra.voltage_v, rb.voltage_v) << n;
    ASSERT_EQ(ra.temp_c, rb.temp_c) << n;
  }
}

TEST(TwinFile, MissingSectionsTakeTheThesisDefaults) {
  const TwinConfig config = twin_from_json(nlohmann::json::object(), "empty.json");
  EXPECT_EQ(config.nominal.coefficients(), PolynomialSensorModel::thesis_eq_3_14().coefficients());
  EXPECT_EQ(config.noise, NoiseSettings{});
  EXPECT_TRUE(config.effects.empty());
}

TEST(TwinFile, BadFilesAreNamedWithTheFieldAndRange) {
  EXPECT_NE(load_error("{\n  \"noise\": {\"voltage_std_v\": 0.1,}\n}")
                .find("bad.json: line 2, column 34: not valid JSON"),
            std::string::npos)
      << load_error("{\n  \"noise\": {\"voltage_std_v\": 0.1,}\n}");
  EXPECT_NE(load_error(R"({"efects": []})").find("unknown field 'efects'"), std::string::npos);
  EXPECT_NE(load_error(R"({"effects": [{"name": "mains_pickup", "params": {"harmonics": 40}}]})")
                .find("bad.json: effects[0]: harmonics = 40 is outside its valid range [1, 20]"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"effects": [{"name": "hum"}]})").find("unknown effect 'hum'"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"noise": {"voltage_std_v": "loud"}})")
                .find("bad.json: noise.voltage_std_v: expected a number"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"noise": {"voltage_std_v": -1}})").find("[0, 10] V"), std::string::npos);
  EXPECT_NE(load_error(R"({"nominal": {"a": [[1, 2], [3]]}})").find("nominal.a[1]"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"nominal": {"a": [[1.16, -0.0036]]}})").find("non-zero V term"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"format": "other/2"})").find("format"), std::string::npos);
  EXPECT_NE(load_error(R"({"effects": [{"name": "vibration"}, {"name": "vibration"}]})")
                .find("switched on twice"),
            std::string::npos);
  EXPECT_THROW(load_twin(scratch("does_not_exist.json")), BadArgument);
  // A converter's rounding is part of the voltage noise: LSB / sqrt(12) <= voltage_std_v.
  EXPECT_NE(load_error(R"({"noise": {"voltage_std_v": 0.1, "rounding_lsb_v": 0.5}})")
                .find("bad.json: noise.rounding_lsb_v = 0.5 is outside its valid range [0, "
                      "0.34641] V"),
            std::string::npos)
      << load_error(R"({"noise": {"voltage_std_v": 0.1, "rounding_lsb_v": 0.5}})");
  EXPECT_NE(load_error(R"({"noise": {"rounding_lsb_v": -0.1}})").find("noise.rounding_lsb_v"),
            std::string::npos);
  // A volts lag: each value within its range, the weights summing to 1.
  EXPECT_NE(load_error(R"({"effects": [{"name": "thermal_lag_volts", "params": {"tau_2_s": 0}}]})")
                .find("bad.json: effects[0]: tau_2_s = 0 is outside its valid range [1, 3600] s"),
            std::string::npos);
  EXPECT_NE(load_error(R"({"effects": [{"name": "thermal_lag_volts", "params": {"v_per_c": 2}}]})")
                .find("bad.json: effects[0]: v_per_c = 2 is outside its valid range [-1, 1] V/degC"),
            std::string::npos);
  const std::string unweighed = load_error(
      R"({"effects": [{"name": "thermal_lag_volts", "params": {"weight_1": 0.5}}]})");
  EXPECT_NE(unweighed.find("bad.json: effects[0]: weight_1 + weight_2 + weight_3 = 0.5 must be 1"),
            std::string::npos)
      << unweighed;
}

TEST(TwinFile, ARoundingHeldInTheNoiseIsSavedOnlyWhenSet) {
  TwinConfig config;
  EXPECT_FALSE(twin_to_json(config)["noise"].contains("rounding_lsb_v"));
  config.noise.voltage_std_v = 0.1;
  config.noise.rounding_lsb_v = 0.3;
  const TwinConfig back = twin_from_json(twin_to_json(config), "twin.json");
  EXPECT_EQ(back.noise, config.noise);
}

TEST(TwinFile, AnEffectKeepsTheRangesItWasFittedOn) {
  TwinConfig config;
  config.effects.push_back(make_effect_settings("temp_offset_drift", {}, "test"));
  EXPECT_FALSE(twin_to_json(config)["effects"][0].contains("fitted_over"));
  config.effects[0].fitted_over = FittedRanges{2.5, 9.5, 24.9, 69.9};
  const auto json = twin_to_json(config);
  EXPECT_EQ(json["effects"][0]["fitted_over"]["temperature_c"][1], 69.9);
  const TwinConfig back = twin_from_json(json, "twin.json");
  ASSERT_EQ(back.effects.size(), 1u);
  EXPECT_EQ(back.effects[0].fitted_over, config.effects[0].fitted_over);
  EXPECT_TRUE(back.effects[0].fitted_over->contains(2.5, 69.9));
  EXPECT_FALSE(back.effects[0].fitted_over->contains(2.5, 70.0));
  // `--effect` on top of the file keeps them while the parameters stay the fitted ones.
  const std::filesystem::path path =
      std::filesystem::path(FLANGE_BINARY_DIR) / "twin_fitted_over_test.json";
  save_twin(config, path);
  const double fitted_v_per_c = config.effects[0].params.at("offset_v_per_c");
  EXPECT_EQ(twin_with_effects(path, std::nullopt,
                              {fmt::format("temp_offset_drift:offset_v_per_c={}", fitted_v_per_c)})
                .effects[0]
                .fitted_over,
            config.effects[0].fitted_over);
  EXPECT_FALSE(twin_with_effects(path, std::nullopt, {"temp_offset_drift:offset_v_per_c=0.01"})
                   .effects[0]
                   .fitted_over.has_value());
  std::filesystem::remove(path);
}

TEST(TwinFile, BadFittedRangesAreNamedWithTheFieldAndRange) {
  const auto error_of = [](const std::string& fitted_over) {
    return load_error(R"({"effects": [{"name": "temp_offset_drift", "fitted_over": )" +
                      fitted_over + "}]}");
  };
  EXPECT_NE(error_of(R"({"clearance_mm": [2, 9], "temperature_c": [70, 25]})")
                .find("bad.json: effects[0].fitted_over.temperature_c: [70, 25] is not a range "
                      "[low, high] with -40 <= low <= high <= 200 degC"),
            std::string::npos)
      << error_of(R"({"clearance_mm": [2, 9], "temperature_c": [70, 25]})");
  EXPECT_NE(error_of(R"({"clearance_mm": [-1, 9], "temperature_c": [25, 70]})")
                .find("effects[0].fitted_over.clearance_mm: [-1, 9] is not a range"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"clearance_mm": [2, 9, 10], "temperature_c": [25, 70]})")
                .find("effects[0].fitted_over.clearance_mm: expected [low, high]"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"clearance_mm": [2, 9]})").find("fitted_over.temperature_c: missing"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"clearance_mm": [2, 9], "temperature_c": [25, 70], "age": 1})")
                .find("fitted_over"),
            std::string::npos);
}

}  // namespace
}  // namespace flange::sim

namespace flange::sim {
namespace {

TEST(TwinFile, ACalibrationServesAsTheNominalModel) {
  const std::filesystem::path path =
      std::filesystem::path(FLANGE_BINARY_DIR) / "twin_calibration_test.json";
  {
    std::ofstream file(path);
    // Eq. 3.14 as flange calibrate writes it (other fields of model.json are not needed).
    file << R"({"kind": "flange-calibration", "coefficients": [
      {"v_power": 0, "t_power": 0, "a": 1.16}, {"v_power": 0, "t_power": 1, "a": -0.0036},
      {"v_power": 1, "t_power": 0, "a": 0.3672}, {"v_power": 1, "t_power": 1, "a": 0.0006618},
      {"v_power": 2, "t_power": 0, "a": 0.05812}]})";
  }
  const PolynomialSensorModel model = nominal_from_calibration(path);
  const PolynomialSensorModel thesis = PolynomialSensorModel::thesis_eq_3_14();
  ASSERT_EQ(model.coefficients().rows(), thesis.coefficients().rows());
  ASSERT_EQ(model.coefficients().cols(), thesis.coefficients().cols());
  EXPECT_TRUE(model.coefficients().isApprox(thesis.coefficients(), 1e-15));

  std::ofstream(path) << R"({"kind": "something else"})";
  EXPECT_THROW(nominal_from_calibration(path), BadArgument);
}

}  // namespace
}  // namespace flange::sim
