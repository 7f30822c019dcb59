// SPDX-License-Identifier: MIT
// The locomotive manifest: what it accepts (relative files, any channel order, unknown keys with
// a note), a write-and-read round trip, and one line naming file, field and valid range for
// every way it can be wrong.
#include "locomotive_manifest.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "input_error.h"
#include "input_notes.h"
#include "test_files.h"

namespace flange::host {
namespace {

namespace fs = std::filesystem;
using testing::fresh_test_dir;
using testing::write_file;

// A folder with two channel files and a manifest written from `text`.
class LocomotiveManifestTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fresh_test_dir(std::string("locomotive_manifest_") +
                          ::testing::UnitTest::GetInstance()->current_test_info()->name());
    write_file(dir_ / "a.csv", "t_s,clearance_mm,temp_c,voltage_v\n0,2,20,1\n");
    write_file(dir_ / "b.csv", "t_s,clearance_mm,temp_c,voltage_v\n0,2,20,1\n");
  }
  std::string manifest(const std::string& text) {
    return write_file(dir_ / "locomotive.json", text).string();
  }
  // The message load_locomotive_manifest throws for `text`; fails when it does not throw.
  std::string error_for(const std::string& text) {
    const std::string path = manifest(text);
    try {
      load_locomotive_manifest(path);
    } catch (const InputError& error) {
      std::string message = error.what();
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;  // names the file first
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      return message;
    }
    ADD_FAILURE() << "accepted: " << text;
    return "";
  }
  fs::path dir_;
};

constexpr const char* kTwoChannels = R"({"channels": [
  {"channel": 3, "axle": 2, "side": "right", "file": "b.csv"},
  {"channel": 0, "axle": 1, "side": "left", "file": "a.csv"}]})";

TEST_F(LocomotiveManifestTest, ReadsChannelsInChannelOrderWithFilesBesideTheManifest) {
  const LocomotiveManifest m = load_locomotive_manifest(manifest(kTwoChannels));
  ASSERT_EQ(m.channels.size(), 2u);
  EXPECT_EQ(m.channels[0].channel, 0);
  EXPECT_EQ(m.channels[0].axle, 1);
  EXPECT_EQ(m.channels[0].side, ManifestSide::kLeft);
  EXPECT_EQ(m.channels[0].path, dir_ / "a.csv");
  EXPECT_EQ(m.channels[1].channel, 3);
  EXPECT_EQ(wheel_label(m.channels[1]), "axle 2 right");
  EXPECT_EQ(m.channels[1].file, "b.csv");
}

TEST_F(LocomotiveManifestTest, WrittenManifestReadsBack) {
  std::vector<ManifestChannel> channels(2);
  channels[0] = {0, 1, ManifestSide::kLeft, "a.csv", {}, {}, {}};
  // A wheel's own calibration (any existing file: the loader only checks it is there).
  channels[1] = {1, 1, ManifestSide::kRight, "b.csv", {}, "a.csv", {}};
  write_locomotive_manifest(dir_ / "locomotive.json", channels, "flange simulate ...");
  const LocomotiveManifest m = load_locomotive_manifest((dir_ / "locomotive.json").string());
  ASSERT_EQ(m.channels.size(), 2u);
  EXPECT_EQ(m.channels[1].side, ManifestSide::kRight);
  EXPECT_EQ(m.channels[1].path, dir_ / "b.csv");
  EXPECT_TRUE(m.channels[0].calibration.empty());
  EXPECT_EQ(m.channels[1].calibration, "a.csv");
  EXPECT_EQ(m.channels[1].calibration_path, dir_ / "a.csv");
  EXPECT_EQ(channel_file_name(7), "channel_07.csv");
}

TEST_F(LocomotiveManifestTest, UnknownKeysAreIgnoredWithANote) {
  std::ostringstream notes;
  const ScopedInputNotes sink(notes);
  load_locomotive_manifest(manifest(
      R"({"vehicle": "E-01", "channels": [{"channel": 0, "axle": 1, "side": "left",
          "file": "a.csv", "gain": 2}]})"));
  EXPECT_NE(notes.str().find("ignoring field vehicle"), std::string::npos) << notes.str();
  EXPECT_NE(notes.str().find("ignoring field channels[0].gain"), std::string::npos) << notes.str();
}

TEST_F(LocomotiveManifestTest, AMissingManifestIsNamed) {
  const std::string path = (dir_ / "none.json").string();
  try {
    load_locomotive_manifest(path);
    ADD_FAILURE() << "accepted a missing file";
  } catch (const InputError& error) {
    EXPECT_EQ(std::string(error.what()), path + ": cannot open the manifest");
  }
}

struct BadManifest {
  std::string text;
  std::string names;  // a part of the one-line message
};

TEST_F(LocomotiveManifestTest, EveryBadManifestGetsOneLineWithFieldAndRange) {
  const auto one = [](const std::string& fields) { return R"({"channels": [{)" + fields + "}]}"; };
  const std::vector<BadManifest> cases = {
      {"{\"channels\": [", "not valid JSON"},
      {"", "not valid JSON"},
      {"[1, 2]", "expected a JSON object with a channels array"},
      {"{}", "field channels: missing; valid: an array of 1 to 12 channels"},
      {R"({"channels": []})", "field channels: 0 entries; valid: an array of 1 to 12 channels"},
      {R"({"channels": 3})", "field channels: 3; valid"},
      {R"({"channels": [7]})", "field channels[0]: 7 is not an object"},
      {one(R"("axle": 1, "side": "left", "file": "a.csv")"),
       "field channels[0].channel is missing; valid range 0 to 11"},
      {one(R"("channel": 12, "axle": 1, "side": "left", "file": "a.csv")"),
       "field channels[0].channel: 12 is outside its valid range: a whole number 0 to 11"},
      {one(R"("channel": -1, "axle": 1, "side": "left", "file": "a.csv")"),
       "channels[0].channel: -1 is outside its valid range"},
      {one(R"("channel": 1.5, "axle": 1, "side": "left", "file": "a.csv")"),
       "channels[0].channel: 1.5 is outside its valid range"},
      {one(R"("channel": "3", "axle": 1, "side": "left", "file": "a.csv")"),
       "channels[0].channel: \"3\" is outside its valid range"},
      {one(R"("channel": 0, "axle": 7, "side": "left", "file": "a.csv")"),
       "field channels[0].axle: 7 is outside its valid range: a whole number 1 to 6"},
      {one(R"("channel": 0, "axle": 0, "side": "left", "file": "a.csv")"),
       "channels[0].axle: 0 is outside"},
      {one(R"("channel": 0, "axle": 1, "side": "middle", "file": "a.csv")"),
       "field channels[0].side: \"middle\" is not a side; valid: \"left\" or \"right\""},
      {one(R"("channel": 0, "axle": 1, "file": "a.csv")"), "channels[0].side: missing"},
      {one(R"("channel": 0, "axle": 1, "side": "left")"), "field channels[0].file: missing"},
      {one(R"("channel": 0, "axle": 1, "side": "left", "file": "")"), "channels[0].file: \"\""},
      {one(R"("channel": 0, "axle": 1, "side": "left", "file": "gone.csv")"),
       "field channels[0].file: "},
      {R"({"channels": [{"channel": 2, "axle": 1, "side": "left", "file": "a.csv"},
                        {"channel": 2, "axle": 1, "side": "right", "file": "b.csv"}]})",
       "field channels[1].channel: 2 is already channels[0]'s; each channel 0 to 11 at most once"},
      {R"({"channels": [{"channel": 0, "axle": 3, "side": "left", "file": "a.csv"},
                        {"channel": 1, "axle": 3, "side": "left", "file": "b.csv"}]})",
       "field channels[1]: axle 3 left is already channels[0]'s wheel"},
      {R"({"channels": [{"channel": 0, "axle": 1, "side": "left", "file": "a.csv"},
                        {"channel": 1, "axle": 1, "side": "right", "file": "./a.csv"}]})",
       "field channels[1].file: ./a.csv is already channels[0]'s file"},
      {R"({"channels": [{"channel": 0, "axle": 1, "side": "left", "file": "a.csv",
                         "calibration": 3}]})",
       "field channels[0].calibration: 3 is not a file name; valid: the wheel's model.json"},
      {R"({"channels": [{"channel": 0, "axle": 1, "side": "left", "file": "a.csv",
                         "calibration": "gone.json"}]})",
       "field channels[0].calibration: "},
  };
  for (const BadManifest& c : cases) {
    const std::string message = error_for(c.text);
    EXPECT_NE(message.find(c.names), std::string::npos) << c.text << "\n -> " << message;
  }
  // Thirteen channels: one more than a six-axle locomotive has wheels.
  std::string thirteen = R"({"channels": [)";
  for (int k = 0; k < 13; ++k) {
    thirteen += std::string(k ? "," : "") + R"({"channel": 0, "axle": 1, "side": "left", )" +
                R"("file": "a.csv"})";
  }
  EXPECT_NE(error_for(thirteen + "]}").find("field channels: 13 entries"), std::string::npos);
  EXPECT_NE(error_for(one(R"("channel": 0, "axle": 1, "side": "left", "file": "gone.csv")"))
                .find("gone.csv does not exist"),
            std::string::npos);
}

}  // namespace
}  // namespace flange::host
