// SPDX-License-Identifier: MIT
// `flange run`'s output CSV: rows formatted with six decimals and written, on a thread of their own
// when asked. Formatting four numbers a row and the file system's copy are about half of what the
// filtering thread did with the recording read ahead (docs/benchmarks.md, `flange run`); behind it
// on a third thread, the three share the two cores evenly. The file is the same either way, and a
// run that stops on bad input leaves every row given before it (the writer drains its queue).
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <fstream>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <utility>
#include <vector>

#include "thresholds.h"

namespace flange::host {

// A row's flags, a bit each; the flags column lists them in this order, joined by '|'.
enum RowFlag : unsigned {
  kBadRow = 1u << 0,
  kOutsideCalibration = 1u << 1,
  kClipped = 1u << 2,
  kSaturated = 1u << 3,
};
inline constexpr std::pair<RowFlag, std::string_view> kFlagNames[] = {
    {kBadRow, "bad_row"},
    {kOutsideCalibration, "outside_calibration"},
    {kClipped, "clipped"},
    {kSaturated, "saturated"},
};

inline constexpr std::string_view kRunOutputHeader =
    "t_s,clearance_raw_mm,clearance_filt_mm,flange_mm,alarm,flags\n";

// One output row; a bad row (kBadRow) has no raw clearance, and its column stays empty.
struct RunOutputRow {
  double t_s = 0.0;
  double raw_mm = 0.0;
  double filt_mm = 0.0;
  double flange_mm = 0.0;
  AlarmLevel alarm = AlarmLevel::kNone;
  unsigned flags = 0;  // RowFlag bits
};

class RunOutputCsv {
 public:
  // Creates `path` and writes the header (std::runtime_error when it cannot); an earlier regular
  // file there is replaced, not truncated (the .cpp says why). own_thread: format and write the
  // rows on a second thread, behind the caller.
  RunOutputCsv(const std::string& path, bool own_thread);
  // Writes what is still queued; an error then is lost (finish() reports it).
  ~RunOutputCsv();
  RunOutputCsv(const RunOutputCsv&) = delete;
  RunOutputCsv& operator=(const RunOutputCsv&) = delete;

  // Takes `rows` to be written after the ones before, and leaves it empty (its capacity kept,
  // from a block written earlier) for the caller's next rows.
  void write(std::vector<RunOutputRow>& rows);
  // Writes what is queued and closes the file; std::runtime_error when anything failed.
  void finish();

 private:
  void write_now(const std::vector<RunOutputRow>& rows);  // format into the buffer, and out
  void write_behind();                                    // the second thread's loop
  void stop_thread();                                     // drains the queue, joins

  const std::string path_;
  std::ofstream out_;
  std::vector<char> buffer_;  // rows formatted, before they go to the file

  // Blocks between the two threads: filled ones to write, in order, and written ones to reuse.
  std::mutex mutex_;
  std::condition_variable filled_ready_, space_ready_;
  std::deque<std::vector<RunOutputRow>> filled_;
  std::vector<std::vector<RunOutputRow>> spare_;
  bool closing_ = false;
  std::exception_ptr thread_error_;  // bad_alloc on the second thread, raised to the caller
  std::thread thread_;
};

}  // namespace flange::host
