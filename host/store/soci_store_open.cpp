// SPDX-License-Identifier: MIT
// Opening a store: connecting, the SQLite pragmas, the migration, and the errors as one line.
#include <soci/postgresql/soci-postgresql.h>
#include <soci/sqlite3/soci-sqlite3.h>

#include <filesystem>

#include "soci_store.h"
#include "store_schema.h"

namespace flange::host {

namespace {

// SOCI's SQLite connection string quotes a value that has spaces or quotes in it.
std::string sqlite_connection(const std::string& path) {
  std::string quoted = "\"";
  for (const char c : path) {
    if (c == '"') quoted += '"';  // doubled
    quoted += c;
  }
  return "db=" + quoted + "\" timeout=30";
}

void check_sqlite_folder(const StoreUrl& url) {
  const std::filesystem::path path(url.target);
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : ".";
  std::error_code error;
  if (!std::filesystem::is_directory(folder, error)) {
    throw StoreError("store " + url.shown + ": cannot open: folder " + folder.string() +
                     " does not exist");
  }
}

void connect(soci::session& sql, const StoreUrl& url) {
  if (url.backend == StoreBackend::kSqlite) {
    check_sqlite_folder(url);
    sql.open(soci::sqlite3, sqlite_connection(url.target));
    // WAL: readers never block the writer; NORMAL sync keeps every commit atomic (a killed
    // process loses nothing committed), only a power cut may lose the latest commits.
    sql << "PRAGMA foreign_keys = ON";
    std::string mode;
    sql << "PRAGMA journal_mode = WAL", soci::into(mode);
    sql << "PRAGMA synchronous = NORMAL";
  } else {
    sql.open(soci::postgresql, url.target);
    sql << "SET client_min_messages = WARNING";
  }
}

}  // namespace

void throw_store_error(const std::string& store, const char* action, const std::string& what) {
  std::string line;
  bool space = false;
  for (const char c : what) {
    const bool blank = c == '\n' || c == '\r' || c == '\t' || c == ' ';
    if (blank) {
      space = !line.empty();
      continue;
    }
    if (space) line += ' ';
    space = false;
    line += c;
  }
  throw StoreError("store " + store + ": " + action + ": " + line);
}

SociStore::SociStore(const StoreUrl& url, int schema_version) : url_(url) {
  store_guarded(url_.shown, "cannot open", [&] {
    connect(sql_, url_);
    migrate_store(sql_, url_, schema_version);
    schema_version_ = stored_schema_version(sql_, url_);
  });
}

std::string SociStore::backend() const {
  return url_.backend == StoreBackend::kSqlite ? "sqlite" : "postgresql";
}

std::unique_ptr<Store> open_store(const std::string& url) {
  return std::make_unique<SociStore>(parse_store_url(url), kStoreSchemaVersion);
}

std::unique_ptr<Store> open_store_at_schema_version(const std::string& url, int version) {
  if (version < 1 || version > kStoreSchemaVersion) {
    throw std::out_of_range("schema version " + std::to_string(version) + " is outside 1 to " +
                            std::to_string(kStoreSchemaVersion));
  }
  return std::make_unique<SociStore>(parse_store_url(url), version);
}

}  // namespace flange::host
