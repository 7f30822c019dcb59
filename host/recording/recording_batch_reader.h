// SPDX-License-Identifier: MIT
// A recording's rows in batches, read, parsed and checked on a second thread while the caller
// works on the batch before: the reading and number parsing are about half of `flange run`'s
// time. The caller gets the same rows, problems, errors and line numbers as RecordingReader
// gives, in file order (docs/benchmarks.md, `flange run`). Memory stays flat: a few batches of a
// fixed size go round between the two threads.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "input_error.h"
#include "line_blocks.h"
#include "recording_batch.h"
#include "recording_columns.h"
#include "recording_row.h"
#include "time_order.h"

namespace flange::host {

// Bytes of the file per batch: a few thousand rows, enough that handing a batch over between the
// threads costs nothing against its parsing, few enough that the batches stay in the caches.
inline constexpr std::size_t kRecordingBatchBytes = std::size_t{256} << 10;

class RecordingBatchReader {
 public:
  // Opens `path` and checks its header (InputError as RecordingReader). lenient as
  // RecordingReader's. read_ahead: a second thread reads the next batches while the caller works;
  // without it each batch is read when asked for, on the caller's thread.
  RecordingBatchReader(const std::string& path, bool lenient, bool read_ahead);
  ~RecordingBatchReader();
  RecordingBatchReader(const RecordingBatchReader&) = delete;
  RecordingBatchReader& operator=(const RecordingBatchReader&) = delete;

  // The next rows in file order, checked as RecordingReader::next checks them; empty at the end
  // of the file. Valid until the next call. A bad row when not lenient: the rows before it come
  // first, and the next call throws its InputError (so the first bad line of the file is the one
  // reported, whatever the second thread has read beyond it).
  std::span<const RecordingRow> next_rows();

  bool has_run_column() const { return columns_.has_run_column(); }
  std::size_t rows_read() const { return rows_read_; }

 private:
  // The next block's rows into `batch` (on the second thread when reading ahead).
  void fill(RecordingBatch& batch);
  void read_ahead();  // the second thread's loop
  // The next filled batch in file order; the one before goes back to be filled again.
  std::unique_ptr<RecordingBatch> take_filled(std::unique_ptr<RecordingBatch> done);
  // Checks the time order of `batch`'s rows and counts them; the number of rows to return (fewer
  // when a strict read stops at a bad row, whose error then waits in pending_error_).
  std::size_t check_in_order(RecordingBatch& batch);

  const std::string path_;
  const bool lenient_;

  // Filling batches: the second thread's alone once it runs.
  FileLineBlocks blocks_;
  std::unique_ptr<RecordingBatch> first_batch_;  // holds the header's block
  std::optional<std::string_view> first_lines_;  // its lines after the header, until read
  const RecordingColumns columns_;
  std::size_t line_ = 1;  // the last line read (the header is line 1)
  std::vector<std::string_view> fields_;

  // Checking in order: the caller's.
  TimeOrder time_order_;
  std::unique_ptr<RecordingBatch> current_;  // the rows last returned
  std::size_t rows_read_ = 0;
  std::optional<InputError> pending_error_;
  bool at_end_ = false;

  // Batches going round: empty ones to the filler, filled ones to the caller, in order.
  std::mutex mutex_;
  std::condition_variable empty_ready_, filled_ready_;
  std::deque<std::unique_ptr<RecordingBatch>> empty_, filled_;
  bool stopping_ = false;
  std::thread read_ahead_thread_;
};

}  // namespace flange::host
