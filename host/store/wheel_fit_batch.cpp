// SPDX-License-Identifier: MIT
#include "wheel_fit_batch.h"

#include <fmt/format.h>

#include <cmath>
#include <vector>

namespace flange::host {

namespace {

// What one batch adds to one wheel's row of wheel_fit.
struct WheelSums {
  long long wheel_id = 0, runs = 0, runs_since = 0, n = 0, alarms = 0;
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0, syy = 0.0;
  std::optional<std::string> last_at;  // none: the batch has only alarm events on the wheel
  long long last_run_id = 0;
  double last_odometer_km = 0.0;
  std::optional<double> last_wear_mm;
};

// The sums' columns, as the UPDATE's derived table `d` names them, and PostgreSQL types.
const std::pair<const char*, const char*> kColumns[] = {{"wheel_id", "BIGINT"},
                                                        {"runs", "BIGINT"},
                                                        {"runs_since", "BIGINT"},
                                                        {"n", "BIGINT"},
                                                        {"sx", "DOUBLE PRECISION"},
                                                        {"sy", "DOUBLE PRECISION"},
                                                        {"sxx", "DOUBLE PRECISION"},
                                                        {"sxy", "DOUBLE PRECISION"},
                                                        {"syy", "DOUBLE PRECISION"},
                                                        {"alarms", "BIGINT"},
                                                        {"last_at", "TEXT"},
                                                        {"last_run_id", "BIGINT"},
                                                        {"last_odometer_km", "DOUBLE PRECISION"},
                                                        {"last_wear_mm", "DOUBLE PRECISION"}};

// The batch's latest run replaces the wheel's when it is later (time, then run id).
constexpr const char* kSet =
    "UPDATE wheel_fit SET runs = wheel_fit.runs + d.runs,"
    " runs_since = wheel_fit.runs_since + d.runs_since, n = wheel_fit.n + d.n,"
    " sx = wheel_fit.sx + d.sx, sy = wheel_fit.sy + d.sy, sxx = wheel_fit.sxx + d.sxx,"
    " sxy = wheel_fit.sxy + d.sxy, syy = wheel_fit.syy + d.syy,"
    " alarm_events = wheel_fit.alarm_events + d.alarms,"
    " last_at = CASE WHEN {0} THEN d.last_at ELSE wheel_fit.last_at END,"
    " last_run_id = CASE WHEN {0} THEN d.last_run_id ELSE wheel_fit.last_run_id END,"
    " last_odometer_km = CASE WHEN {0} THEN d.last_odometer_km"
    " ELSE wheel_fit.last_odometer_km END,"
    " last_wear_mm = CASE WHEN {0} THEN d.last_wear_mm ELSE wheel_fit.last_wear_mm END"
    " FROM {1} WHERE wheel_fit.wheel_id = d.wheel_id";
constexpr const char* kNewer =
    "d.last_at IS NOT NULL AND (d.last_at > wheel_fit.last_at OR (d.last_at ="
    " wheel_fit.last_at AND d.last_run_id > wheel_fit.last_run_id))";

// A PostgreSQL array literal's element: NULL, a number, or quoted text.
std::string element(const std::optional<std::string>& text, bool quoted) {
  if (!text) return "NULL";
  if (!quoted) return *text;
  std::string out = "\"";
  for (const char c : *text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + '"';
}

std::optional<std::string> number(double value) {
  return std::isfinite(value) ? std::optional(fmt::format("{}", value)) : std::nullopt;
}

// One wheel's sums as text, in the order of kColumns (NULL as nullopt).
std::vector<std::optional<std::string>> as_text(const WheelSums& s) {
  return {std::to_string(s.wheel_id),
          std::to_string(s.runs),
          std::to_string(s.runs_since),
          std::to_string(s.n),
          number(s.sx),
          number(s.sy),
          number(s.sxx),
          number(s.sxy),
          number(s.syy),
          std::to_string(s.alarms),
          s.last_at,
          std::to_string(s.last_run_id),
          number(s.last_odometer_km),
          s.last_wear_mm ? number(*s.last_wear_mm) : std::nullopt};
}

// PostgreSQL: the sums as one array per column, unnested in one UPDATE (one round trip).
void update_postgresql(soci::session& sql, const std::vector<WheelSums>& sums) {
  constexpr std::size_t kCount = std::size(kColumns);
  std::vector<std::string> literals(kCount, "{");
  for (const WheelSums& wheel : sums) {
    const auto values = as_text(wheel);
    for (std::size_t c = 0; c < kCount; ++c) {
      if (literals[c].size() > 1) literals[c] += ',';
      literals[c] += element(values[c], std::string(kColumns[c].second) == "TEXT");
    }
  }
  std::string arrays, names;
  for (std::size_t c = 0; c < kCount; ++c) {
    literals[c] += '}';
    arrays += fmt::format("{}CAST(:c{} AS {}[])", c ? ", " : "", c, kColumns[c].second);
    names += fmt::format("{}{}", c ? ", " : "", kColumns[c].first);
  }
  soci::statement update(sql);
  for (std::string& literal : literals) update.exchange(soci::use(literal));
  update.alloc();
  update.prepare(fmt::format(kSet, kNewer, fmt::format("unnest({}) AS d ({})", arrays, names)));
  update.define_and_bind();
  update.execute(true);
}

// SQLite: one prepared UPDATE run once per wheel through SOCI's bulk binding (in-process).
void update_sqlite(soci::session& sql, const std::vector<WheelSums>& sums) {
  constexpr std::size_t kCount = std::size(kColumns);
  std::vector<std::vector<std::string>> values(kCount);
  std::vector<std::vector<soci::indicator>> present(kCount);
  for (const WheelSums& wheel : sums) {
    const auto row = as_text(wheel);
    for (std::size_t c = 0; c < kCount; ++c) {
      values[c].push_back(row[c].value_or(""));
      present[c].push_back(row[c] ? soci::i_ok : soci::i_null);
    }
  }
  std::string select;
  for (std::size_t c = 0; c < kCount; ++c) {
    // Bound as text: CAST gives each its column's type, as the stored sums have.
    const char* type = std::string(kColumns[c].second) == "BIGINT" ? "INTEGER"
                       : std::string(kColumns[c].second) == "TEXT" ? "TEXT"
                                                                   : "REAL";
    select += fmt::format("{}CAST(:c{} AS {}) AS {}", c ? ", " : "", c, type, kColumns[c].first);
  }
  soci::statement update(sql);
  for (std::size_t c = 0; c < kCount; ++c) update.exchange(soci::use(values[c], present[c]));
  update.alloc();
  update.prepare(fmt::format(kSet, kNewer, "(SELECT " + select + ") AS d"));
  update.define_and_bind();
  update.execute(true);
}

}  // namespace

void WheelFitBatch::add_run(long long wheel_id, const std::string& started_at, long long run_id,
                            double odometer_km, const std::optional<double>& wear_mm) {
  wheels_[wheel_id].rows.push_back({started_at, run_id, odometer_km, wear_mm});
}

void WheelFitBatch::add_alarm(long long wheel_id) { ++wheels_[wheel_id].alarms; }

// Each wheel's row created when missing, locked, and its since_at read (the time its fit starts).
std::vector<std::string> WheelFitBatch::lock_rows(soci::session& sql, StoreBackend backend) const {
  std::vector<long long> ids;
  for (const auto& [id, wheel] : wheels_) ids.push_back(id);
  std::vector<std::string> since(ids.size());
  if (backend == StoreBackend::kPostgresql) {
    std::string array = "{";
    for (const long long id : ids) array += fmt::format("{}{}", array.size() > 1 ? "," : "", id);
    array += "}";
    sql << "INSERT INTO wheel_fit (wheel_id) SELECT unnest(CAST(:ids AS BIGINT[]))"
           " ON CONFLICT (wheel_id) DO NOTHING",
        soci::use(array);
    std::vector<long long> found(ids.size());
    // In wheel order, so that two writers lock their common wheels in the same order.
    sql << "SELECT wheel_id, since_at FROM wheel_fit WHERE wheel_id ="
           " ANY(CAST(:ids AS BIGINT[])) ORDER BY wheel_id FOR UPDATE",
        soci::use(array), soci::into(found), soci::into(since);
    if (found != ids) throw soci::soci_error("wheel_fit: rows of the batch's wheels missing");
    return since;
  }
  // SQLite: the transaction holds the write lock already.
  sql << "INSERT INTO wheel_fit (wheel_id) VALUES (:id) ON CONFLICT (wheel_id) DO NOTHING",
      soci::use(ids);
  long long id = 0;
  std::string at;
  soci::statement read = (sql.prepare << "SELECT since_at FROM wheel_fit WHERE wheel_id = :id",
                          soci::use(id), soci::into(at));
  for (std::size_t i = 0; i < ids.size(); ++i) {
    id = ids[i];
    read.execute(true);
    since[i] = at;
  }
  return since;
}

void WheelFitBatch::apply(soci::session& sql, StoreBackend backend) {
  if (wheels_.empty()) return;
  const std::vector<std::string> since = lock_rows(sql, backend);
  std::vector<WheelSums> sums;
  std::size_t i = 0;
  for (const auto& [id, wheel] : wheels_) {
    WheelSums s;
    s.wheel_id = id;
    s.alarms = wheel.alarms;
    for (const Row& row : wheel.rows) {
      ++s.runs;
      const bool latest = !s.last_at || row.started_at > *s.last_at ||
                          (row.started_at == *s.last_at && row.run_id > s.last_run_id);
      if (latest) {
        s.last_at = row.started_at;
        s.last_run_id = row.run_id;
        s.last_odometer_km = row.odometer_km;
        s.last_wear_mm = row.wear_mm;
      }
      if (row.started_at < since[i]) continue;  // before the wheel's latest maintenance
      ++s.runs_since;
      if (!row.wear_mm) continue;
      const double x = row.odometer_km, y = *row.wear_mm;
      ++s.n;
      s.sx += x;
      s.sy += y;
      s.sxx += x * x;
      s.sxy += x * y;
      s.syy += y * y;
    }
    sums.push_back(std::move(s));
    ++i;
  }
  if (backend == StoreBackend::kPostgresql) {
    update_postgresql(sql, sums);
  } else {
    update_sqlite(sql, sums);
  }
  wheels_.clear();
}

}  // namespace flange::host
