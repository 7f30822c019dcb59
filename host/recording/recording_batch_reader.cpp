// SPDX-License-Identifier: MIT
#include "recording_batch_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace flange::host {

namespace {

// Batches going round when reading ahead: one with the caller, the others being filled or
// filled and waiting, so that neither thread waits for the other while their speeds differ a
// little.
constexpr int kBatchesReadingAhead = 4;

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
  // The header's block is claimed first: it is at the front.
  empty_.push_back(std::move(first_batch_));
  if (!read_ahead) return;
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

void RecordingBatchReader::claim_next_block(RecordingBatch& batch) {
  batch.sequence = next_sequence_++;
  batch.lines = {};
  batch.size = 0;
  batch.line_count = 0;
  batch.end_of_file = false;
  batch.error = nullptr;
  try {
    if (first_lines_) {
      batch.lines = *std::exchange(first_lines_, std::nullopt);  // `batch` holds the header's block
    } else if (blocks_.next(batch.text)) {
      batch.lines = batch.text.text();
    } else {
      batch.end_of_file = true;
      file_done_ = true;
    }
  } catch (...) {
    batch.error = std::current_exception();  // raised in file order, when the caller gets here
    file_done_ = true;
  }
}

void RecordingBatchReader::read_ahead() {
  for (;;) {
    std::unique_ptr<RecordingBatch> batch;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      empty_ready_.wait(lock, [this] { return stopping_ || file_done_ || !empty_.empty(); });
      if (stopping_ || file_done_) return;
      batch = std::move(empty_.front());
      empty_.pop_front();
      claim_next_block(*batch);
    }
    batch->read_rows(columns_);
    {
      const std::lock_guard<std::mutex> lock(mutex_);
      filled_.push_back(std::move(batch));
    }
    filled_ready_.notify_one();
  }
}

std::unique_ptr<RecordingBatch> RecordingBatchReader::take_in_order(
    std::unique_ptr<RecordingBatch> done) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (done) {
    empty_.push_back(std::move(done));
    empty_ready_.notify_one();
  }
  for (;;) {
    const auto next = std::find_if(filled_.begin(), filled_.end(), [this](const auto& batch) {
      return batch->sequence == expected_sequence_;
    });
    if (next != filled_.end()) {
      std::unique_ptr<RecordingBatch> batch = std::move(*next);
      filled_.erase(next);
      ++expected_sequence_;
      return batch;
    }
    if (next_sequence_ == expected_sequence_) {
      // Nobody has the next block yet: read it here rather than wait for the second thread.
      // Every batch is free then (the ones before are returned, none after is claimed).
      std::unique_ptr<RecordingBatch> batch = std::move(empty_.front());
      empty_.pop_front();
      claim_next_block(*batch);
      lock.unlock();
      batch->read_rows(columns_);
      ++expected_sequence_;
      return batch;
    }
    filled_ready_.wait(lock);  // the second thread is reading it
  }
}

std::span<const RecordingRow> RecordingBatchReader::next_rows() {
  if (pending_error_) throw *pending_error_;
  if (current_ && current_->error) std::rethrow_exception(current_->error);
  while (!at_end_) {
    current_ = take_in_order(std::move(current_));
    if (current_->error) std::rethrow_exception(current_->error);
    if (current_->end_of_file) {
      at_end_ = true;
      if (rows_read_ == 0) throw no_data_rows(path_, last_line_);
      break;
    }
    const std::size_t count = check_in_order(*current_);
    if (count > 0) return {current_->rows.data(), count};
    if (pending_error_) throw *pending_error_;
  }
  return {};
}

std::size_t RecordingBatchReader::check_in_order(RecordingBatch& batch) {
  const std::size_t first_line = last_line_;
  last_line_ += batch.line_count;
  for (std::size_t k = 0; k < batch.size; ++k) {
    RecordingRow& row = batch.rows[k];
    row.line += first_line;
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
