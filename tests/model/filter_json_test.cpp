// SPDX-License-Identifier: MIT
// The filter.json loader: the checked-in sets load; bad input fails with one line naming the file
// and the field.
#include "filter_json.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

namespace flange::model {
namespace {

std::filesystem::path set_json(const std::string& set) {
  return std::filesystem::path(FLANGE_SOURCE_DIR) / "coeffs" / set / "filter.json";
}

TEST(FilterJson, LoadsTheCheckedInSets) {
  const CoreConfig vehicle = load_core_config(set_json("vehicle_sos"));
  EXPECT_EQ(vehicle.num_sections, 4);
  EXPECT_EQ(vehicle.section_order, 2);
  EXPECT_EQ(vehicle.coef_frac_bits, 16);
  EXPECT_EQ(vehicle.feedback_shift, 9);
  EXPECT_EQ(vehicle.split_shift(), 17);
  ASSERT_EQ(vehicle.rom.size(), 48u);
  EXPECT_EQ(vehicle.rom[0], 62660);   // section 0's lo word of b0
  EXPECT_EQ(vehicle.rom[8], 64478);   // its hi word of -a1 (a first-order section)
  EXPECT_EQ(vehicle.rom[10], 1);      // E1 = round(-a1)
  EXPECT_EQ(vehicle.error_feedback(1), (std::vector<std::int64_t>{2, -1}));

  const CoreConfig df1 = load_core_config(set_json("measurement_df1"));
  EXPECT_EQ(df1.num_sections, 1);
  EXPECT_EQ(df1.section_order, 5);
  EXPECT_EQ(df1.rom_depth(), 27);

  const FloatDesign design = load_float_design(set_json("measurement_sos"));
  EXPECT_DOUBLE_EQ(design.fs_hz, 6.0);
  ASSERT_TRUE(design.fc_hz.has_value());
  EXPECT_EQ(design.sos.size(), 3u);
  EXPECT_EQ(design.b.size(), 6u);
  EXPECT_DOUBLE_EQ(design.leftover_gain, 1.0);
}

TEST(FilterJson, RomMatchesTheReadmemhImage) {
  // coeffs.mem (what the RTL reads) and quantized.words (what the model reads) are one ROM.
  for (const std::string set : {"measurement_sos", "measurement_df1", "vehicle_sos"}) {
    const CoreConfig c = load_core_config(set_json(set));
    std::ifstream mem(set_json(set).parent_path() / "coeffs.mem");
    std::vector<std::int64_t> words;
    std::string line;
    while (std::getline(mem, line)) {
      if (line.empty() || line.starts_with("//")) continue;
      std::int64_t w = std::stoll(line, nullptr, 16);
      if (w >= (std::int64_t{1} << (c.coef_width - 1))) w -= std::int64_t{1} << c.coef_width;
      words.push_back(w);
    }
    EXPECT_EQ(words, c.rom) << set;
  }
}

class BadFilterJson : public ::testing::Test {
 protected:
  void SetUp() override {
    std::ifstream in(set_json("vehicle_sos"));
    good_ = nlohmann::json::parse(in);
    path_ =
        std::filesystem::temp_directory_path() /
        ("flange_bad_" +
         std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + ".json");
  }
  void TearDown() override { std::filesystem::remove(path_); }

  // The error of loading `text` (both loaders tried; the core one first).
  std::string error_of(const std::string& text, bool float_side = false) {
    std::ofstream(path_) << text;
    try {
      if (float_side) {
        load_float_design(path_);
      } else {
        load_core_config(path_);
      }
    } catch (const FilterJsonError& e) {
      return e.what();
    }
    return "";
  }
  std::string error_of(const nlohmann::json& j, bool float_side = false) {
    return error_of(j.dump(1), float_side);
  }

  void expect_names(const std::string& error, const std::string& field) {
    EXPECT_NE(error.find(path_.string()), std::string::npos) << error;
    EXPECT_NE(error.find(field), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << "one line: " << error;
  }

  nlohmann::json good_;
  std::filesystem::path path_;
};

TEST_F(BadFilterJson, NotJson) {
  const std::string error = error_of(std::string("{\"quantized\": [1, 2"));
  expect_names(error, "not valid JSON");
}

TEST_F(BadFilterJson, MissingFile) {
  std::filesystem::remove(path_);
  try {
    load_core_config(path_);
    FAIL() << "no error";
  } catch (const FilterJsonError& e) {
    expect_names(e.what(), "cannot open");
  }
}

TEST_F(BadFilterJson, MissingQuantized) {
  good_.erase("quantized");
  expect_names(error_of(good_), "'quantized'");
}

TEST_F(BadFilterJson, WrongType) {
  good_["quantized"]["split_shift"] = "17";
  expect_names(error_of(good_), "'quantized.split_shift'");
}

TEST_F(BadFilterJson, WordOutOfRange) {
  good_["quantized"]["words"][3] = 200000;  // does not fit 18 bits
  expect_names(error_of(good_), "'quantized.words[3]'");
}

TEST_F(BadFilterJson, TooFewWords) {
  good_["quantized"]["words"].erase(0);
  expect_names(error_of(good_), "'quantized.words'");
}

TEST_F(BadFilterJson, InconsistentShift) {
  good_["quantized"]["split_shift"] = 16;  // must be coef_bits - 1
  expect_names(error_of(good_), "'quantized.split_shift'");
  good_["quantized"]["split_shift"] = 17;
  good_["quantized"]["coef_frac_bits"] = 26;  // the error word would not fit D + s = 25 bits
  expect_names(error_of(good_), "'quantized.coef_frac_bits'");
}

TEST_F(BadFilterJson, RomDepthDisagrees) {
  good_["quantized"]["rom_depth"] = 21;
  expect_names(error_of(good_), "'quantized.rom_depth'");
}

TEST_F(BadFilterJson, SosRowTooShort) {
  good_["sos"][1] = {1.0, 2.0};
  expect_names(error_of(good_, true), "'sos[1]'");
}

TEST_F(BadFilterJson, NonFiniteGain) {
  good_["leftover_gain"] = "inf";
  expect_names(error_of(good_, true), "'leftover_gain'");
}

}  // namespace
}  // namespace flange::model
