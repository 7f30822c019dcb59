// SPDX-License-Identifier: MIT
// The two backends the store tests run on: a SQLite file in the test's folder, and a fresh
// database on a throwaway PostgreSQL server. Under CTest the server is the StorePostgres fixture's
// (FLANGE_TEST_POSTGRES_STATE names its state file); run by hand, the test program starts its
// own on first use and stops it at exit (postgres_server.sh both ways).
#pragma once

#include <string>

namespace flange::testing {

enum class StoreBackendUnderTest { kSqlite, kPostgresql };

// "Sqlite" / "Postgresql": the parameter's name in test names.
std::string backend_test_name(StoreBackendUnderTest backend);

// A URL of a new, empty store, unique to `name` (a test's name) within this process.
std::string fresh_store_url(StoreBackendUnderTest backend, const std::string& name);

// The folder of the PostgreSQL server's Unix socket (starting the server when needed).
std::string postgres_socket_folder();

// Runs one statement on the store behind `url` outside flange (to set up what flange refuses
// to write itself, e.g. a newer schema version). Fails the test on an error.
void execute_sql(const std::string& url, const std::string& statement);

}  // namespace flange::testing
