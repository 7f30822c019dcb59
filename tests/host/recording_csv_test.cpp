// SPDX-License-Identifier: MIT
// The recording reader: header, numbers, ranges, time order; strict and lenient.
#include "recording_csv.h"

#include <gtest/gtest.h>

#include <sstream>

#include "input_error.h"
#include "input_notes.h"
#include "test_files.h"

namespace flange::host {
namespace {

using testing::fresh_test_dir;
using testing::write_file;

// `folder`: one of each test's own, since CTest runs the tests of this file in parallel.
std::string read_error(const std::string& text, const std::string& folder = "csv") {
  const auto path = write_file(fresh_test_dir(folder) / "input.csv", text);
  try {
    RecordingReader reader(path.string());
    while (reader.next()) {
    }
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(RecordingCsv, ReadsRowsInAnyColumnOrderWithOptionalReference) {
  const auto path = write_file(fresh_test_dir("csv_ok") / "ok.csv",
                               "voltage_v,t_s,temp_c,clearance_mm,run\n"
                               "1.5,0,20,2.0,a\n"
                               "1.6,0.5,21,,a\n"
                               "1.7,0,22,2.5,b\n");
  RecordingReader reader(path.string());
  EXPECT_TRUE(reader.has_run_column());
  auto first = reader.next();
  ASSERT_TRUE(first);
  EXPECT_EQ(first->voltage_v, 1.5);
  EXPECT_EQ(first->clearance_mm.value(), 2.0);
  EXPECT_EQ(first->line, 2u);
  auto second = reader.next();
  ASSERT_TRUE(second);
  EXPECT_FALSE(second->clearance_mm.has_value());
  auto third = reader.next();  // time restarts in a new run
  ASSERT_TRUE(third);
  EXPECT_EQ(third->run, "b");
  EXPECT_FALSE(reader.next());
  EXPECT_EQ(reader.rows_read(), 3u);
}

TEST(RecordingCsv, EveryBadInputNamesFileLineAndColumn) {
  const std::string header = "t_s,clearance_mm,temp_c,voltage_v\n";
  struct Case {
    std::string text;
    std::string expected;
  };
  const Case cases[] = {
      {"t_s,clearance_mm,temp_c\n0,1,20\n", ":1: missing column 'voltage_v'"},
      {header, ":2: no data rows (the file holds only the header"},
      {header + "\n\n", ":4: no data rows"},
      {"", ":1: empty file"},
      {header + "0,1,20\n", ":2: expected 4 fields, found 3"},
      {header + "0,1,20,abc\n", ":2: column 4 (voltage_v): 'abc' is not a finite number"},
      {header + "0,1,nan,5\n", ":2: column 3 (temp_c): 'nan' is not a finite number"},
      {header + "0,1,inf,5\n", ":2: column 3 (temp_c): 'inf' is not a finite number"},
      {header + "0,1,20,5\n0,1,20,5\n", ":3: column 1 (t_s): 0 is not after the previous time 0"},
      {header + "1,1,20,5\n0.5,1,20,5\n", ":3: column 1 (t_s): 0.5 is not after"},
      {header + "0,1,20,11.5\n",
       ":2: column 4 (voltage_v): 11.5 is outside the valid range -1 to 11 V (the sensor's 0 to 10 "
       "V and 1 V either side for noise)"},
      {header + "0,1,20,-1.1\n", ":2: column 4 (voltage_v): -1.1 is outside"},
      {header + "0,1,250,5\n",
       ":2: column 3 (temp_c): 250 is outside the valid range -40 to 200 C"},
      {header + "0,x,20,5\n", ":2: column 2 (clearance_mm): 'x' is not a finite number"},
  };
  for (const Case& c : cases) {
    const std::string error = read_error(c.text);
    EXPECT_NE(error.find("input.csv"), std::string::npos) << error;
    EXPECT_NE(error.find(c.expected), std::string::npos) << "got: " << error;
  }
}

TEST(RecordingCsv, AByteOrderMarkIsSkipped) {
  const auto path = write_file(fresh_test_dir("csv_bom") / "excel.csv",
                               "\xEF\xBB\xBFt_s,clearance_mm,temp_c,voltage_v\r\n0,1,20,5\r\n");
  RecordingReader reader(path.string());
  const auto row = reader.next();
  ASSERT_TRUE(row);
  EXPECT_EQ(row->t_s, 0.0);
  EXPECT_EQ(row->voltage_v, 5.0);
}

TEST(RecordingCsv, ExtraColumnsAreIgnoredWithOneNote) {
  const auto path = write_file(fresh_test_dir("csv_extra") / "logger.csv",
                               "t_s,speed_kmh,clearance_mm,temp_c,humidity,voltage_v\n"
                               "0,80,1,20,55,5\n"
                               "1,81,1.1,20,55,5.1\n");
  std::ostringstream notes;
  {
    const ScopedInputNotes sink(notes);
    RecordingReader reader(path.string());
    const auto first = reader.next();
    ASSERT_TRUE(first);
    EXPECT_EQ(first->clearance_mm.value(), 1.0);
    EXPECT_EQ(first->voltage_v, 5.0);
    const auto second = reader.next();
    ASSERT_TRUE(second);
    EXPECT_EQ(second->temp_c, 20.0);
    EXPECT_FALSE(reader.next());
  }
  EXPECT_EQ(notes.str(),
            "note: " + path.string() +
                ":1: ignoring column(s) 'speed_kmh', 'humidity': not part of the recording format "
                "t_s,clearance_mm,temp_c,voltage_v[,run]\n");
}

TEST(RecordingCsv, ABinaryFileIsRefusedInOneLine) {
  std::string bytes = "PK\x03\x04";
  bytes += std::string(1, '\0');
  bytes += "\x14\x00\x06\x00garbage";
  const std::string error = read_error(bytes, "csv_binary");
  EXPECT_NE(error.find("input.csv: not a text file (a zero byte at offset 4)"), std::string::npos)
      << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

TEST(RecordingCsv, NonPrintableBytesInAFieldAreEscapedAndCut) {
  const std::string error = read_error(
      "t_s,clearance_mm,temp_c,voltage_v\n0,1,20,\x01\x7f\xff" + std::string(100, 'x') + "\n",
      "csv_escape");
  EXPECT_NE(error.find("'\\x01\\x7F\\xFF" + std::string(37, 'x') + "...' is not a finite number"),
            std::string::npos)
      << error;
}

TEST(RecordingCsv, LenientModeFlagsBadRowsAndGoesOn) {
  const auto path = write_file(fresh_test_dir("csv_lenient") / "mixed.csv",
                               "t_s,clearance_mm,temp_c,voltage_v\n"
                               "0,1,20,5\n"
                               "1,1,20,bad\n"
                               "2,1,20,12\n"
                               "3,1,20,5\n");
  RecordingReader reader(path.string(), /*lenient=*/true);
  int good = 0;
  int flagged = 0;
  while (auto row = reader.next()) (row->problem.empty() ? good : flagged)++;
  EXPECT_EQ(good, 2);
  EXPECT_EQ(flagged, 2);
}

}  // namespace
}  // namespace flange::host
