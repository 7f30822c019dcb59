// SPDX-License-Identifier: MIT
// The batch reader, with and without its second thread, against the row reader: the same rows,
// problems and errors; the first bad line of a file is the one reported, however far the second
// thread has read beyond it.
#include "recording_batch_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include "input_error.h"
#include "recording_csv.h"
#include "test_files.h"

namespace flange::host {
namespace {

using testing::fresh_test_dir;
using testing::write_file;

const std::string kHeader = "t_s,clearance_mm,temp_c,voltage_v,run\n";

// Replaces field `index` (0-based) of a row's text: t_s, clearance_mm, temp_c, voltage_v, run.
void set_field(std::string& row, int index, const std::string& value) {
  std::size_t begin = 0;
  for (int k = 0; k < index; ++k) begin = row.find(',', begin) + 1;
  row.replace(begin, row.find(',', begin) - begin, value);
}

// `rows` rows of a 6 Hz recording in two runs (time restarts), some without a reference, a blank
// line now and then; `change(line, text)` may rewrite any row's text. Line n holds row n - 1 until
// the first blank line (after row 999).
std::string recording(int rows,
                      const std::function<void(int line, std::string& text)>& change = {}) {
  std::string text = kHeader;
  int line = 1;
  for (int k = 0; k < rows; ++k) {
    const int run = k < rows / 2 ? 0 : 1;
    const int in_run = run == 0 ? k : k - rows / 2;
    std::string row = std::to_string(in_run / 6.0) + "," +
                      (k % 5 == 0 ? std::string() : std::to_string(2.0 + (k % 700) * 0.01)) +
                      "," + std::to_string(20.0 + (k % 90) * 0.5) + "," +
                      std::to_string(1.0 + (k % 800) * 0.01) + ",run" + std::to_string(run);
    if (change) change(line + 1, row);
    text += row + "\n";
    ++line;
    if (k % 1000 == 999) {
      text += "\n";
      ++line;
    }
  }
  return text;
}

// An error as a last "row" of the rows read.
RecordingRow error_row(const InputError& error) {
  RecordingRow row;
  row.problem = std::string("error: ") + error.what();
  return row;
}

// Every row the row reader returns, its error (if any) after them as a last "row".
std::vector<RecordingRow> rows_of_row_reader(const std::string& path, bool lenient) {
  std::vector<RecordingRow> rows;
  try {
    RecordingReader reader(path, lenient);
    while (std::optional<RecordingRow> row = reader.next()) rows.push_back(*row);
  } catch (const InputError& error) {
    rows.push_back(error_row(error));
  }
  return rows;
}

std::vector<RecordingRow> rows_of_batch_reader(const std::string& path, bool lenient,
                                               bool read_ahead) {
  std::vector<RecordingRow> rows;
  try {
    RecordingBatchReader reader(path, lenient, read_ahead);
    for (std::span<const RecordingRow> batch; !(batch = reader.next_rows()).empty();) {
      rows.insert(rows.end(), batch.begin(), batch.end());
    }
    EXPECT_TRUE(reader.next_rows().empty());  // and stays at the end
  } catch (const InputError& error) {
    rows.push_back(error_row(error));
  }
  return rows;
}

void expect_same_rows(const std::vector<RecordingRow>& expected,
                      const std::vector<RecordingRow>& got, const std::string& what) {
  ASSERT_EQ(got.size(), expected.size()) << what;
  for (std::size_t k = 0; k < got.size(); ++k) {
    const RecordingRow& e = expected[k];
    const RecordingRow& g = got[k];
    ASSERT_TRUE(g.line == e.line && g.t_s == e.t_s && g.clearance_mm == e.clearance_mm &&
                g.temp_c == e.temp_c && g.voltage_v == e.voltage_v && g.run == e.run &&
                g.problem == e.problem)
        << what << ": row " << k << ", line " << e.line << ": expected '" << e.problem
        << "', got line " << g.line << " '" << g.problem << "'";
  }
}

// The last "row" of rows_of_*: the error, or "" when the file read to its end.
std::string error_of(const std::vector<RecordingRow>& rows) {
  if (rows.empty() || rows.back().problem.rfind("error: ", 0) != 0) return "";
  return rows.back().problem;
}

TEST(RecordingBatchReader, ReturnsTheRowsAndProblemsOfTheRowReader) {
  // Bad rows of every kind, in the first batch and in later ones; 30,000 rows are about 1.3 MB,
  // five batches.
  int bad_rows = 0;
  const std::string text = recording(30000, [&bad_rows](int line, std::string& row) {
    const std::string before = row;
    if (line % 4001 == 0) row = "1,2,3";             // too few fields
    if (line % 5003 == 0) set_field(row, 0, "0");    // time goes back
    if (line % 6007 == 0) set_field(row, 3, "x");    // voltage not a number
    if (line % 7001 == 0) set_field(row, 2, "300");  // temperature out of range
    if (line % 9001 == 0) {                          // both: the time order is named
      set_field(row, 0, "0");
      set_field(row, 3, "-2");
    }
    if (row != before) ++bad_rows;
  });
  const std::string path = write_file(fresh_test_dir("batch_same") / "in.csv", text).string();
  for (const bool lenient : {true, false}) {
    const std::vector<RecordingRow> expected = rows_of_row_reader(path, lenient);
    if (lenient) {
      EXPECT_EQ(std::count_if(expected.begin(), expected.end(),
                              [](const RecordingRow& row) { return !row.problem.empty(); }),
                bad_rows);
    } else {
      EXPECT_NE(error_of(expected).find("in.csv:4001: expected 5 fields, found 3"),
                std::string::npos);
    }
    for (const bool read_ahead : {false, true}) {
      expect_same_rows(expected, rows_of_batch_reader(path, lenient, read_ahead),
                       std::string(lenient ? "lenient" : "strict") +
                           (read_ahead ? ", read ahead" : ", one thread"));
    }
  }
}

TEST(RecordingBatchReader, ABadLineInALaterBatchIsReportedWithItsLine) {
  // Line 25,025 is past the first batches (256 KiB, about 5,800 rows each) and past blank lines.
  const std::string text = recording(30000, [](int line, std::string& row) {
    if (line == 25025) set_field(row, 3, "x");
  });
  const std::string path = write_file(fresh_test_dir("batch_late") / "late.csv", text).string();
  for (const bool read_ahead : {false, true}) {
    const std::vector<RecordingRow> rows = rows_of_batch_reader(path, false, read_ahead);
    EXPECT_NE(error_of(rows).find("late.csv:25025: column 4 (voltage_v): 'x' is not a finite number"),
              std::string::npos)
        << error_of(rows);
    EXPECT_EQ(error_of(rows).find('\n'), std::string::npos);
    ASSERT_GE(rows.size(), 2u);
    EXPECT_EQ(rows[rows.size() - 2].line, 25024u);  // every row before it, none after
    EXPECT_EQ(rows.size() - 1, 24999u);  // lines 2 to 25,024: 24 blank lines and 24,999 rows
  }
}

TEST(RecordingBatchReader, TheFirstOfTwoBadLinesWins) {
  // The second bad line is found while the rows are read (by the second thread, ahead); the first
  // only by the time order, which waits for the rows before it. Then the other way round.
  const auto late_number_early_time = [](int line, std::string& row) {
    if (line == 9000) set_field(row, 0, "0");  // time goes back
    if (line == 26000) set_field(row, 3, "x");
  };
  const auto early_range_late_time = [](int line, std::string& row) {
    if (line == 9000) set_field(row, 3, "12.5");  // voltage out of range
    if (line == 9001) row = "1,2,3,4,5,6";
    if (line == 26000) set_field(row, 0, "0");
  };
  const std::string dir = fresh_test_dir("batch_first").string();
  const std::string first =
      write_file(dir + "/a.csv", recording(30000, late_number_early_time)).string();
  const std::string second =
      write_file(dir + "/b.csv", recording(30000, early_range_late_time)).string();
  for (const bool read_ahead : {false, true}) {
    EXPECT_NE(error_of(rows_of_batch_reader(first, false, read_ahead))
                  .find("a.csv:9000: column 1 (t_s): 0 is not after the previous time"),
              std::string::npos)
        << error_of(rows_of_batch_reader(first, false, read_ahead));
    EXPECT_NE(error_of(rows_of_batch_reader(second, false, read_ahead))
                  .find("b.csv:9000: column 4 (voltage_v): 12.5 is outside"),
              std::string::npos)
        << error_of(rows_of_batch_reader(second, false, read_ahead));
  }
}

TEST(RecordingBatchReader, FilesWithoutRowsFailAsTheRowReaderFails) {
  const std::string dir = fresh_test_dir("batch_empty").string();
  const std::string cases[] = {"", kHeader, kHeader + "\n\n", "t_s,temp_c\n0,1\n",
                               std::string("PK\x03\x04\0garbage", 12), kHeader + "0,1,20,5,a"};
  int n = 0;
  for (const std::string& text : cases) {
    const std::string path = write_file(dir + "/" + std::to_string(n++) + ".csv", text).string();
    const std::vector<RecordingRow> expected = rows_of_row_reader(path, false);
    for (const bool read_ahead : {false, true}) {
      expect_same_rows(expected, rows_of_batch_reader(path, false, read_ahead), path);
    }
  }
}

}  // namespace
}  // namespace flange::host
