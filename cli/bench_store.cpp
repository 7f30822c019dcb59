// SPDX-License-Identifier: MIT
#include "bench_store.h"

#include <fmt/format.h>

#include <filesystem>
#include <map>

#include "content_sha256.h"
#include "input_error.h"
#include "recording_csv.h"

namespace flange::cli {

namespace {

struct Session {
  std::vector<host::BenchRow> rows;
  std::string canonical;  // the rows as text, for the session's hash
};

// The file's sessions in order of first appearance (every row read before anything is stored).
std::vector<std::pair<std::string, Session>> read_sessions(const std::string& csv) {
  host::RecordingReader reader(csv);
  const std::string stem = std::filesystem::path(csv).stem().string();
  std::vector<std::pair<std::string, Session>> sessions;
  std::map<std::string, std::size_t> index;
  while (const std::optional<host::RecordingRow> row = reader.next()) {
    const std::string label = reader.has_run_column() ? row->run : stem;
    auto [at, added] = index.emplace(label, sessions.size());
    if (added) sessions.emplace_back(label, Session{});
    Session& session = sessions[at->second].second;
    session.rows.push_back({row->t_s, row->clearance_mm, row->temp_c, row->voltage_v});
    session.canonical += fmt::format("{},{},{},{}\n", row->t_s,
                                     row->clearance_mm ? fmt::format("{}", *row->clearance_mm) : "",
                                     row->temp_c, row->voltage_v);
  }
  if (sessions.empty()) throw host::InputError(csv + ": no data rows to import");
  return sessions;
}

double sample_rate_hz(const std::vector<host::BenchRow>& rows) {
  if (rows.size() < 2) return 0.0;
  const double span = rows.back().t_s - rows.front().t_s;
  return span > 0.0 ? static_cast<double>(rows.size() - 1) / span : 0.0;
}

}  // namespace

BenchImport import_bench_csv(host::Store& store, const std::string& csv, const std::string& sensor,
                             const std::string& imported_at) {
  BenchImport import;
  const std::size_t before = store.sessions(host::SessionKind::kBench).size();
  for (const auto& [label, session] : read_sessions(csv)) {
    host::SessionRecord record;
    record.kind = host::SessionKind::kBench;
    record.label = label;
    record.started_at = imported_at;  // a bench CSV carries no clock time
    record.sample_rate_hz = sample_rate_hz(session.rows);
    record.source_file = csv;
    record.source_sha256 = host::text_sha256(session.canonical);
    record.sensor_serial = sensor;
    store.record_session(record, session.rows);
    ++import.sessions;
    import.rows += session.rows.size();
  }
  import.new_sessions = store.sessions(host::SessionKind::kBench).size() - before;
  return import;
}

std::vector<host::RecordingRow> stored_bench_rows(host::Store& store,
                                                  std::vector<std::int64_t>& session_ids) {
  std::vector<host::RecordingRow> rows;
  session_ids.clear();
  for (const auto& [id, session] : store.sessions(host::SessionKind::kBench)) {
    session_ids.push_back(id);
    for (const host::BenchRow& bench : store.bench_rows(id)) {
      host::RecordingRow row;
      row.line = rows.size() + 1;
      row.t_s = bench.t_s;
      row.clearance_mm = bench.clearance_mm;
      row.temp_c = bench.temp_c;
      row.voltage_v = bench.voltage_v;
      row.run = session.label;
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace flange::cli
