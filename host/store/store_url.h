// SPDX-License-Identifier: MIT
// Store URLs: "sqlite:PATH" (a file; created when missing) and "postgresql://[USER[:PASSWORD]@]
// [HOST][:PORT]/DBNAME[?KEY=VALUE&...]" (libpq's own URI form, which it parses; e.g. a Unix
// socket folder as ?host=/tmp/pg). "postgres://" is accepted as its alias.
#pragma once

#include <string>

namespace flange::host {

enum class StoreBackend { kSqlite, kPostgresql };

struct StoreUrl {
  StoreBackend backend = StoreBackend::kSqlite;
  std::string target;  // sqlite: the file path; postgresql: the URI as given
  std::string shown;   // the URL for messages, a password replaced by "***"
};

// Throws StoreUrlError (one line naming the URL and the forms accepted).
StoreUrl parse_store_url(const std::string& url);

}  // namespace flange::host
