// SPDX-License-Identifier: MIT
// `flange calibrate --store`: the calibration database's bench sessions in the store, the
// regression refitted from every bench session stored, each refit kept as a calibration.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "calibration.h"
#include "recording_row.h"
#include "store.h"

namespace flange::cli {

struct BenchImport {
  std::size_t sessions = 0;      // run labels in the file
  std::size_t new_sessions = 0;  // ... not yet in the store
  std::size_t rows = 0;
};

// Imports a recording-format CSV (a calibration database or one new session) as bench
// sessions, one per run label (the file's stem when it has no run column), each with every row.
// A session is known by its label and the SHA-256 of its rows (canonical text, so a session
// that comes again inside a grown database is not stored twice). `sensor` may be "".
// Throws InputError for a bad row (nothing imported then).
BenchImport import_bench_csv(host::Store& store, const std::string& csv, const std::string& sensor,
                             const std::string& imported_at);

// Every bench session's rows, session by session in the order they were stored, each row
// labelled with its session's label; the sessions' ids in `session_ids`.
std::vector<host::RecordingRow> stored_bench_rows(host::Store& store,
                                                  std::vector<std::int64_t>& session_ids);

}  // namespace flange::cli
