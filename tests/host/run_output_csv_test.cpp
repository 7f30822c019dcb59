// SPDX-License-Identifier: MIT
// flange run's output CSV: the same bytes whether written behind on a thread of its own or on the
// caller's, every row given before a stop written, and the errors it owes.
#include "run_output_csv.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace flange::host {
namespace {

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Blocks of rows of every kind: flags alone and together, a bad row (no raw clearance), each
// alarm, negative and long numbers; 3 blocks of 4096 and a short one.
std::vector<std::vector<RunOutputRow>> sample_blocks() {
  std::vector<std::vector<RunOutputRow>> blocks(4);
  int n = 0;
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const int rows = b + 1 < blocks.size() ? 4096 : 123;
    for (int k = 0; k < rows; ++k, ++n) {
      RunOutputRow row;
      row.t_s = n / 6.0 + 12345678.0 * (n % 1000 == 999);
      row.raw_mm = 1.5 + 0.001 * (n % 997) - 3.0 * (n % 7 == 0);
      row.filt_mm = 1.4 + 0.0003 * (n % 991);
      row.flange_mm = 33.0 - row.filt_mm;
      row.alarm = static_cast<AlarmLevel>(n % 3);
      row.flags = static_cast<unsigned>(n % 16);
      blocks[b].push_back(row);
    }
  }
  return blocks;
}

std::string write_blocks(const std::filesystem::path& path, bool own_thread,
                         std::size_t stop_after) {
  {
    RunOutputCsv out(path.string(), own_thread);
    std::vector<RunOutputRow> rows;
    const auto blocks = sample_blocks();
    for (std::size_t b = 0; b < blocks.size() && b < stop_after; ++b) {
      rows = blocks[b];
      out.write(rows);
      EXPECT_TRUE(rows.empty());
    }
    if (stop_after >= blocks.size()) out.finish();
    // else: destroyed unfinished, as when bad input stops a run
  }
  return read_file(path);
}

class RunOutputCsvTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("flange_run_output_csv_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path dir_;
};

TEST_F(RunOutputCsvTest, BehindOnItsOwnThreadTheFileIsTheSame) {
  const std::string alone = write_blocks(dir_ / "one.csv", false, 99);
  const std::string behind = write_blocks(dir_ / "two.csv", true, 99);
  EXPECT_EQ(alone, behind);
  EXPECT_EQ(alone.rfind(kRunOutputHeader, 0), 0u);
  EXPECT_EQ(std::count(alone.begin(), alone.end(), '\n'), 1 + 3 * 4096 + 123);
  // Row 0: no flags, alarm none; row 1: bad_row, so no raw clearance; row 15: every flag.
  std::istringstream lines(alone);
  std::string line;
  std::vector<std::string> first;
  for (int k = 0; k < 17 && std::getline(lines, line); ++k) first.push_back(line);
  EXPECT_EQ(first[1], "0.000000,-1.500000,1.400000,31.600000,none,");
  EXPECT_EQ(first[2], "0.166667,,1.400300,31.599700,warning,bad_row");
  EXPECT_EQ(first[16],
            "2.500000,,1.404500,31.595500,none,bad_row|outside_calibration|clipped|saturated");
}

TEST_F(RunOutputCsvTest, AStoppedRunKeepsEveryRowGivenBeforeTheStop) {
  for (const bool own_thread : {false, true}) {
    const std::string two_blocks = write_blocks(dir_ / "stopped.csv", own_thread, 2);
    EXPECT_EQ(std::count(two_blocks.begin(), two_blocks.end(), '\n'), 1 + 2 * 4096) << own_thread;
  }
}

ino_t inode_of(const std::filesystem::path& path) {
  struct stat status {};
  EXPECT_EQ(::stat(path.c_str(), &status), 0) << path;
  return status.st_ino;
}

// An earlier output of one name is removed and written anew (truncating it costs ext4 a flush at
// close); through a symbolic link or a second hard link the file is written in place as before.
TEST_F(RunOutputCsvTest, AnEarlierOutputIsReplacedAndLinksAreWrittenThrough) {
  const std::string fresh = write_blocks(dir_ / "fresh.csv", true, 99);
  const std::string longer_old_text(2 * fresh.size(), 'x');

  const std::filesystem::path plain = dir_ / "plain.csv";
  std::ofstream(plain) << longer_old_text;
  std::ifstream old_file(plain, std::ios::binary);  // sees the old file's bytes while open
  EXPECT_EQ(write_blocks(plain, true, 99), fresh);
  std::stringstream old_bytes;
  old_bytes << old_file.rdbuf();
  EXPECT_EQ(old_bytes.str(), longer_old_text);  // replaced, not truncated and overwritten

  const std::filesystem::path target = dir_ / "target.csv", link = dir_ / "link.csv";
  std::ofstream(target) << longer_old_text;
  std::filesystem::create_symlink(target, link);
  EXPECT_EQ(write_blocks(link, false, 99), fresh);
  EXPECT_TRUE(std::filesystem::is_symlink(link));
  EXPECT_EQ(read_file(target), fresh);

  const std::filesystem::path first = dir_ / "first.csv", second = dir_ / "second.csv";
  std::ofstream(first) << longer_old_text;
  std::filesystem::create_hard_link(first, second);
  EXPECT_EQ(write_blocks(first, true, 99), fresh);
  EXPECT_EQ(read_file(second), fresh);
  EXPECT_EQ(inode_of(first), inode_of(second));

  // A file we may not write is not replaced behind its permissions: the open refuses it.
  if (::geteuid() != 0) {  // root may write anything
    const std::filesystem::path read_only = dir_ / "read_only.csv";
    std::ofstream(read_only) << longer_old_text;
    std::filesystem::permissions(read_only, std::filesystem::perms::owner_read);
    EXPECT_THROW(RunOutputCsv(read_only.string(), false), std::runtime_error);
    EXPECT_EQ(read_file(read_only), longer_old_text);
  }
}

TEST_F(RunOutputCsvTest, AFileThatCannotBeCreatedIsAnError) {
  for (const bool own_thread : {false, true}) {
    EXPECT_THROW(RunOutputCsv((dir_ / "no_such_folder" / "out.csv").string(), own_thread),
                 std::runtime_error);
  }
}

TEST_F(RunOutputCsvTest, AWriteThatFailsIsReportedWhenFinishing) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full on this system";
  for (const bool own_thread : {false, true}) {
    RunOutputCsv out("/dev/full", own_thread);
    std::vector<RunOutputRow> rows = sample_blocks()[0];
    out.write(rows);
    EXPECT_THROW(out.finish(), std::runtime_error) << own_thread;
  }
}

}  // namespace
}  // namespace flange::host
