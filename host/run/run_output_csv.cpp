// SPDX-License-Identifier: MIT
#include "run_output_csv.h"

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
  out_.open(path, std::ios::binary);
  if (!out_) throw std::runtime_error("cannot write " + path);
  out_ << kRunOutputHeader;
  buffer_.resize(kOutputChunkBytes + kMaxRowChars);  // a chunk and the row that ends it
  if (own_thread) thread_ = std::thread([this] { write_behind(); });
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
