// SPDX-License-Identifier: MIT
#include "run_output_csv.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <stdexcept>

#include "fixed_decimals.h"

namespace flange::host {

namespace {

// Blocks queued for the second thread at most: enough that neither thread waits for the other
// while their speeds differ a little, few enough that memory stays flat.
constexpr std::size_t kBlocksWritingBehind = 4;
// Bytes formatted before they go to the file: a few thousand rows.
constexpr std::size_t kOutputChunkBytes = std::size_t{1} << 18;

constexpr std::size_t kMaxAlarmChars = 8;  // "critical", the longest alarm_name()
constexpr std::size_t kMaxFlagsChars = [] {
  std::size_t chars = 0;
  for (const auto& flag : kFlagNames) chars += flag.second.size() + 1;  // a name and its '|'
  return chars;
}();
// The longest output row: four numbers, the alarm, every flag, five commas and the newline.
constexpr std::size_t kMaxRowChars = 4 * kMaxFixed6Chars + kMaxAlarmChars + kMaxFlagsChars + 6;

// Unlinks an earlier output at `path` before it is written again, when it is a regular file of
// one name, and returns a descriptor that holds it until closed (-1 when nothing was unlinked).
// Truncating it instead costs a 1 M-row run a fifth of its time on ext4: a file cut to zero and
// written again is flushed to the disk at close (auto_da_alloc). Its blocks are freed, and
// discarded, when the last descriptor closes, which the writing thread does while the others
// work (docs/benchmarks.md, `flange run`). A symbolic link, a second hard link or a device
// (/dev/null) is written through as before; a file that cannot be unlinked, or that we may not
// write, is left to the open, which reports it.
int unlink_earlier_output(const std::string& path) {
  struct stat status {};
  if (::lstat(path.c_str(), &status) != 0 || !S_ISREG(status.st_mode) || status.st_nlink != 1 ||
      ::access(path.c_str(), W_OK) != 0) {  // a read-only file stays the open's to refuse
    return -1;
  }
  const int held = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (held < 0) return -1;
  if (::unlink(path.c_str()) != 0) {
    ::close(held);
    return -1;
  }
  return held;
}

char* append(char* at, std::string_view text) {
  std::memcpy(at, text.data(), text.size());
  return at + text.size();
}

// One output row at `at` (room for kMaxRowChars).
char* format_row(char* at, const RunOutputRow& row) {
  at = write_fixed6(at, row.t_s);
  *at++ = ',';
  if ((row.flags & kBadRow) == 0) at = write_fixed6(at, row.raw_mm);
  *at++ = ',';
  at = write_fixed6(at, row.filt_mm);
  *at++ = ',';
  at = write_fixed6(at, row.flange_mm);
  *at++ = ',';
  at = append(at, alarm_name(row.alarm));
  *at++ = ',';
  bool first = true;
  for (const auto& [flag, name] : kFlagNames) {
    if ((row.flags & flag) == 0) continue;
    if (!first) *at++ = '|';
    at = append(at, name);
    first = false;
  }
  *at++ = '\n';
  return at;
}

}  // namespace

RunOutputCsv::RunOutputCsv(const std::string& path, bool own_thread) : path_(path) {
  const int earlier = unlink_earlier_output(path);
  out_.open(path, std::ios::binary);
  if (!out_) {
    if (earlier >= 0) ::close(earlier);
    throw std::runtime_error("cannot write " + path);
  }
  out_ << kRunOutputHeader;
  buffer_.resize(kOutputChunkBytes + kMaxRowChars);  // a chunk and the row that ends it
  if (!own_thread) {
    if (earlier >= 0) ::close(earlier);
    return;
  }
  thread_ = std::thread([this, earlier] {
    if (earlier >= 0) ::close(earlier);  // frees the earlier output's blocks, off the others' way
    write_behind();
  });
}

RunOutputCsv::~RunOutputCsv() { stop_thread(); }

void RunOutputCsv::write(std::vector<RunOutputRow>& rows) {
  if (!thread_.joinable()) {
    write_now(rows);
    rows.clear();
    return;
  }
  std::unique_lock<std::mutex> lock(mutex_);
  space_ready_.wait(lock,
                    [this] { return thread_error_ || filled_.size() < kBlocksWritingBehind; });
  if (thread_error_) std::rethrow_exception(thread_error_);
  filled_.push_back(std::move(rows));
  rows.clear();  // a moved-from vector is valid but unspecified
  if (!spare_.empty()) {
    rows = std::move(spare_.back());
    spare_.pop_back();
  }
  lock.unlock();
  filled_ready_.notify_one();
}

void RunOutputCsv::write_now(const std::vector<RunOutputRow>& rows) {
  char* const start = buffer_.data();
  char* at = start;
  for (const RunOutputRow& row : rows) {
    at = format_row(at, row);
    if (static_cast<std::size_t>(at - start) >= kOutputChunkBytes) {
      out_.write(start, at - start);
      at = start;
    }
  }
  // Block by block, so that a run stopped by bad input leaves the rows before it in the file.
  out_.write(start, at - start);
}

void RunOutputCsv::write_behind() {
  try {
    for (;;) {
      std::vector<RunOutputRow> rows;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        filled_ready_.wait(lock, [this] { return closing_ || !filled_.empty(); });
        if (filled_.empty()) return;  // closing, and everything written
        rows = std::move(filled_.front());
        filled_.pop_front();
      }
      space_ready_.notify_one();
      write_now(rows);
      rows.clear();
      const std::lock_guard<std::mutex> lock(mutex_);
      spare_.push_back(std::move(rows));
    }
  } catch (...) {
    const std::lock_guard<std::mutex> lock(mutex_);
    thread_error_ = std::current_exception();
    space_ready_.notify_all();  // the caller must not wait for room any more
  }
}

void RunOutputCsv::stop_thread() {
  if (!thread_.joinable()) return;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  filled_ready_.notify_all();
  thread_.join();
}

void RunOutputCsv::finish() {
  stop_thread();
  if (thread_error_) std::rethrow_exception(thread_error_);
  out_.close();
  if (!out_) throw std::runtime_error("cannot write " + path_);
}

}  // namespace flange::host
