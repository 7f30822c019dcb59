// SPDX-License-Identifier: MIT
// A recording's rows in batches, read, parsed and checked on a second thread while the caller
// works on the batch before: the reading and number parsing are about half of `flange run`'s
// time. When the next batch is not ready and the second thread has not started it (it is behind,
// or the machine's other work has it waiting), the caller reads that batch itself rather than
// wait. The caller gets the same rows, problems, errors and line numbers as RecordingReader
// gives, in file order (docs/benchmarks.md, `flange run`). Memory stays flat: a few batches of a
// fixed size go round between the two threads.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <cstdint>
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
  // Gives `batch` the next block of the file and its sequence number (mutex_ held: the file is
  // read in order); marks the file done at its end or on an error.
  void claim_next_block(RecordingBatch& batch);
  void read_ahead();  // the second thread's loop
  // The next batch in file order; `done` (the rows returned before) goes back to be refilled.
  std::unique_ptr<RecordingBatch> take_in_order(std::unique_ptr<RecordingBatch> done);
  // Numbers the lines of `batch`'s rows, checks their time order and counts them; the number of
  // rows to return (fewer when a strict read stops at a bad row, whose error then waits in
  // pending_error_).
  std::size_t check_in_order(RecordingBatch& batch);

  const std::string path_;
  const bool lenient_;

  // Claiming blocks: under mutex_.
  FileLineBlocks blocks_;
  std::unique_ptr<RecordingBatch> first_batch_;  // holds the header's block
  std::optional<std::string_view> first_lines_;  // its lines after the header, until claimed
  std::uint64_t next_sequence_ = 0;              // of the next block claimed
  bool file_done_ = false;                       // no block is left to claim
  // From the header (read with the members above, so declared after them); const, so both threads
  // read rows with it.
  const RecordingColumns columns_;

  // Checking in order: the caller's.
  TimeOrder time_order_;
  std::unique_ptr<RecordingBatch> current_;  // the rows last returned
  std::uint64_t expected_sequence_ = 0;      // of the next batch to return
  std::size_t last_line_ = 1;                // the last line returned (the header is line 1)
  std::size_t rows_read_ = 0;
  std::optional<InputError> pending_error_;
  bool at_end_ = false;

  // Batches going round: empty ones to be claimed, filled ones (in any order) to the caller.
  std::mutex mutex_;
  std::condition_variable empty_ready_, filled_ready_;
  std::deque<std::unique_ptr<RecordingBatch>> empty_;
  std::vector<std::unique_ptr<RecordingBatch>> filled_;
  bool stopping_ = false;
  std::thread read_ahead_thread_;
};

}  // namespace flange::host
