// SPDX-License-Identifier: MIT
#include "store_test_backends.h"

#include <gtest/gtest.h>
#include <libpq-fe.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>

#include "test_files.h"

namespace flange::testing {

namespace {

const std::string kServerScript =
    std::string(FLANGE_SOURCE_DIR) + "/tests/host/store/postgres_server.sh";

// The server this process started itself (none under CTest's fixture); stopped at exit.
class OwnPostgresServer : public ::testing::Environment {
 public:
  std::string folder() {
    if (folder_.empty()) {
      state_ = std::filesystem::temp_directory_path() /
               ("flange_store_test_pg_" + std::to_string(::getpid()));
      const std::string start = "bash " + kServerScript + " start " + state_.string();
      if (std::system(start.c_str()) != 0) {
        ADD_FAILURE() << "could not start a PostgreSQL server: " << start;
        return "";
      }
      std::ifstream(state_) >> folder_;
    }
    return folder_;
  }
  void TearDown() override {
    if (folder_.empty()) return;
    const std::string stop = "bash " + kServerScript + " stop " + state_.string();
    EXPECT_EQ(std::system(stop.c_str()), 0) << stop;
    folder_.clear();
  }

 private:
  std::filesystem::path state_;
  std::string folder_;
};

OwnPostgresServer* own_server() {
  static OwnPostgresServer* server = [] {
    auto* created = new OwnPostgresServer;  // gtest owns it once added
    ::testing::AddGlobalTestEnvironment(created);
    return created;
  }();
  return server;
}

// Registered before main runs, so that gtest calls its TearDown at the end.
[[maybe_unused]] const OwnPostgresServer* const kRegistered = own_server();

std::string postgres_url(const std::string& database) {
  return "postgresql://flange@/" + database + "?host=" + postgres_socket_folder();
}

void postgres_execute(const std::string& url, const std::string& statement) {
  std::unique_ptr<PGconn, decltype(&PQfinish)> connection(PQconnectdb(url.c_str()), &PQfinish);
  ASSERT_EQ(PQstatus(connection.get()), CONNECTION_OK) << PQerrorMessage(connection.get());
  std::unique_ptr<PGresult, decltype(&PQclear)> result(PQexec(connection.get(), statement.c_str()),
                                                       &PQclear);
  const auto status = PQresultStatus(result.get());
  ASSERT_TRUE(status == PGRES_COMMAND_OK || status == PGRES_TUPLES_OK)
      << statement << ": " << PQerrorMessage(connection.get());
}

void sqlite_execute(const std::string& path, const std::string& statement) {
  sqlite3* raw = nullptr;
  const int opened = sqlite3_open(path.c_str(), &raw);
  std::unique_ptr<sqlite3, decltype(&sqlite3_close)> connection(raw, &sqlite3_close);
  ASSERT_EQ(opened, SQLITE_OK) << path;
  char* message = nullptr;
  const int done = sqlite3_exec(raw, statement.c_str(), nullptr, nullptr, &message);
  const std::string why = message ? message : "";
  sqlite3_free(message);
  ASSERT_EQ(done, SQLITE_OK) << statement << ": " << why;
}

}  // namespace

std::string backend_test_name(StoreBackendUnderTest backend) {
  return backend == StoreBackendUnderTest::kSqlite ? "Sqlite" : "Postgresql";
}

std::string postgres_socket_folder() {
  if (const char* state = std::getenv("FLANGE_TEST_POSTGRES_STATE"); state && *state) {
    std::string folder;
    std::ifstream(state) >> folder;
    if (!folder.empty()) return folder;
    ADD_FAILURE() << "FLANGE_TEST_POSTGRES_STATE=" << state << " names no server folder";
  }
  return own_server()->folder();
}

std::string fresh_store_url(StoreBackendUnderTest backend, const std::string& name) {
  static int serial = 0;
  const std::string unique =
      name + "_" + std::to_string(::getpid()) + "_" + std::to_string(++serial);
  if (backend == StoreBackendUnderTest::kSqlite) {
    return "sqlite:" + (fresh_test_dir("store/" + unique) / "store.db").string();
  }
  std::string database = "t_";
  for (const char c : unique) {
    const auto byte = static_cast<unsigned char>(c);
    database += std::isalnum(byte) ? static_cast<char>(std::tolower(byte)) : '_';
  }
  database = database.substr(0, 60);
  postgres_execute(postgres_url("postgres"), "CREATE DATABASE " + database);
  return postgres_url(database);
}

void execute_sql(const std::string& url, const std::string& statement) {
  if (url.rfind("sqlite:", 0) == 0) {
    sqlite_execute(url.substr(7), statement);
  } else {
    postgres_execute(url, statement);
  }
}

}  // namespace flange::testing
