// SPDX-License-Identifier: MIT
#include "recording_batch_reader.h"

#include <fmt/format.h>

#include <utility>

namespace flange::host {

namespace {

// Batches going round when reading ahead: one with the caller, one being filled, one filled and
// waiting, so that neither thread waits for the other while their speeds differ a little.
constexpr int kBatchesReadingAhead = 3;

// The header from the first block of `blocks`, read into `first`; `first_lines` is left at the
// lines after it.
RecordingColumns read_columns(const std::string& path, FileLineBlocks& blocks,
                              RecordingBatch& first, std::optional<std::string_view>& first_lines) {
  LineCursor unread({});
  const std::string_view header = read_recording_header(path, blocks, first.text, unread);
  first_lines = unread.rest();
  return RecordingColumns(path, header);
}

}  // namespace

RecordingBatchReader::RecordingBatchReader(const std::string& path, bool lenient, bool read_ahead)
    : path_(path),
      lenient_(lenient),
      blocks_(path, kRecordingBatchBytes),
      first_batch_(std::make_unique<RecordingBatch>()),
      columns_(read_columns(path, blocks_, *first_batch_, first_lines_)) {
  if (!read_ahead) return;
  empty_.push_back(std::move(first_batch_));
  for (int k = 1; k < kBatchesReadingAhead; ++k) {
    empty_.push_back(std::make_unique<RecordingBatch>());
  }
  read_ahead_thread_ = std::thread([this] { this->read_ahead(); });
}

RecordingBatchReader::~RecordingBatchReader() {
  if (!read_ahead_thread_.joinable()) return;
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  empty_ready_.notify_all();
  read_ahead_thread_.join();
}

void RecordingBatchReader::fill(RecordingBatch& batch) {
  batch.size = 0;
  batch.end_of_file = false;
  batch.error = nullptr;
  try {
    std::string_view lines;
    if (first_lines_) {
      lines = *std::exchange(first_lines_, std::nullopt);  // `batch` holds the header's block
    } else if (blocks_.next(batch.text)) {
      lines = batch.text.text();
    } else {
      batch.end_of_file = true;
    }
    batch.read_rows(lines, columns_, line_, fields_);
  } catch (...) {
    // Raised in file order, when the caller gets to this batch (bad_alloc on a huge line).
    batch.error = std::current_exception();
  }
}

void RecordingBatchReader::read_ahead() {
  for (;;) {
    std::unique_ptr<RecordingBatch> batch;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      empty_ready_.wait(lock, [this] { return stopping_ || !empty_.empty(); });
      if (stopping_) return;
      batch = std::move(empty_.front());
      empty_.pop_front();
    }
    fill(*batch);
    const bool last = batch->end_of_file || batch->error;
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      filled_.push_back(std::move(batch));
    }
    filled_ready_.notify_one();
    if (last) return;
  }
}

std::unique_ptr<RecordingBatch> RecordingBatchReader::take_filled(
    std::unique_ptr<RecordingBatch> done) {
  if (!read_ahead_thread_.joinable()) {
    if (!done) done = std::move(first_batch_);
    fill(*done);
    return done;
  }
  std::unique_lock<std::mutex> lock(mutex_);
  if (done) {
    empty_.push_back(std::move(done));
    empty_ready_.notify_one();
  }
  filled_ready_.wait(lock, [this] { return !filled_.empty(); });
  std::unique_ptr<RecordingBatch> batch = std::move(filled_.front());
  filled_.pop_front();
  return batch;
}

std::span<const RecordingRow> RecordingBatchReader::next_rows() {
  if (pending_error_) throw *pending_error_;
  if (current_ && current_->error) std::rethrow_exception(current_->error);
  while (!at_end_) {
    current_ = take_filled(std::move(current_));
    if (current_->error) std::rethrow_exception(current_->error);
    if (current_->end_of_file) {
      at_end_ = true;
      if (rows_read_ == 0) throw no_data_rows(path_, current_->last_line);
      break;
    }
    const std::size_t count = check_in_order(*current_);
    if (count > 0) return {current_->rows.data(), count};
    if (pending_error_) throw *pending_error_;
  }
  return {};
}

std::size_t RecordingBatchReader::check_in_order(RecordingBatch& batch) {
  for (std::size_t k = 0; k < batch.size; ++k) {
    RecordingRow& row = batch.rows[k];
    // Only a row that read has its time order checked; it comes before the range problems.
    if (!batch.t_texts[k].empty() && !time_order_.passes(row)) {
      row.problem = time_order_.problem(batch.t_texts[k], columns_.t_column());
    }
    ++rows_read_;
    if (!lenient_ && !row.problem.empty()) {
      pending_error_ = InputError(fmt::format("{}:{}: {}", path_, row.line, row.problem));
      return k;
    }
  }
  return batch.size;
}

}  // namespace flange::host
