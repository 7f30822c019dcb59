// SPDX-License-Identifier: MIT
// Store URLs: malformed ones are bad arguments; stores that cannot be reached, read-only files
// and files that are not stores are one-line StoreErrors naming the store.
#include "store_url.h"

#include <gtest/gtest.h>
#include <pwd.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>

#include "store.h"
#include "store_test_backends.h"
#include "test_files.h"

namespace flange::testing {
namespace {

using host::StoreError;
using host::StoreUrlError;

// The message of the StoreError `url` raises on opening ("" when none).
std::string open_error(const std::string& url) {
  try {
    host::open_store(url);
  } catch (const StoreError& error) {
    return error.what();
  }
  return "";
}

TEST(StoreUrl, ParsesBothForms) {
  const auto sqlite = host::parse_store_url("sqlite:data/fleet.db");
  EXPECT_EQ(sqlite.backend, host::StoreBackend::kSqlite);
  EXPECT_EQ(sqlite.target, "data/fleet.db");
  EXPECT_EQ(host::parse_store_url("sqlite:///var/fleet.db").target, "/var/fleet.db");
  const auto postgres = host::parse_store_url("postgresql://depot:s3cret@db.example:5433/fleet");
  EXPECT_EQ(postgres.backend, host::StoreBackend::kPostgresql);
  EXPECT_EQ(postgres.target, "postgresql://depot:s3cret@db.example:5433/fleet");
  EXPECT_EQ(postgres.shown, "postgresql://depot:***@db.example:5433/fleet");
  EXPECT_EQ(host::parse_store_url("postgres:///fleet?host=/tmp&password=x").shown,
            "postgres:///fleet?host=/tmp&password=***");
}

TEST(StoreUrl, MalformedUrlsAreBadArguments) {
  for (const std::string url : {"", "fleet.db", "sqlite:", "mysql://host/db", "postgresql://",
                                "postgresql://host/db?nosuchoption=1", "postgresql://%zz/db"}) {
    try {
      host::parse_store_url(url);
      ADD_FAILURE() << url << " was accepted";
    } catch (const StoreUrlError& error) {
      const std::string message = error.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_NE(message.find("sqlite:PATH or postgresql://"), std::string::npos) << message;
    }
  }
}

TEST(StoreUrl, AnUnreachableServerIsOneLineNamingTheStore) {
  const auto dir = fresh_test_dir("store_url/unreachable");
  const std::string url = "postgresql://flange:pw@/fleet?host=" + dir.string();
  const std::string message = open_error(url);
  EXPECT_NE(message.find("store postgresql://flange:***@/fleet?host="), std::string::npos)
      << message;
  EXPECT_NE(message.find("cannot open"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  EXPECT_EQ(message.find("pw"), std::string::npos) << message;
}

TEST(StoreUrl, AnUnknownRoleOrDatabaseOnARealServerIsRefused) {
  const std::string host = "?host=" + postgres_socket_folder();
  for (const std::string& url :
       {"postgresql://nobody@/postgres" + host, "postgresql://flange@/no_such_database" + host}) {
    const std::string message = open_error(url);
    EXPECT_NE(message.find("store " + url), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(StoreUrl, AWrongPasswordIsRefusedWithoutShowingIt) {
  const std::string host = "?host=" + postgres_socket_folder();
  const std::string message = open_error("postgresql://password_check:wrong@/postgres" + host);
  EXPECT_NE(message.find("store postgresql://password_check:***@/postgres"), std::string::npos)
      << message;
  EXPECT_NE(message.find("password authentication failed"), std::string::npos) << message;
  EXPECT_EQ(message.find("wrong"), std::string::npos) << message;
  std::string right = fresh_store_url(StoreBackendUnderTest::kPostgresql, "password_check");
  right.replace(right.find("flange@"), 7, "password_check:right@");
  EXPECT_EQ(open_error(right), "");
}

TEST(StoreUrl, SqliteFilesThatCannotBeStoresAreRefused) {
  const auto dir = fresh_test_dir("store_url/sqlite");
  EXPECT_NE(open_error("sqlite:" + (dir / "missing/fleet.db").string()).find("does not exist"),
            std::string::npos);
  const auto text = write_file(dir / "notes.txt", std::string(4096, 'x'));
  EXPECT_NE(open_error("sqlite:" + text.string()).find("store sqlite:"), std::string::npos);
  EXPECT_EQ(std::filesystem::file_size(text), 4096u);  // untouched
}

// As root (CI), a child process drops to "nobody" first: root writes read-only files.
TEST(StoreUrl, AReadOnlyStoreFileIsRefused) {
  const auto dir = fresh_test_dir("store_url/read_only");
  const std::string url = "sqlite:" + (dir / "fleet.db").string();
  host::open_store(url)->upsert_locomotive({"L1", ""});
  std::filesystem::permissions(dir / "fleet.db", std::filesystem::perms::owner_read |
                                                     std::filesystem::perms::group_read |
                                                     std::filesystem::perms::others_read);
  std::filesystem::permissions(
      dir, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec |
               std::filesystem::perms::others_read | std::filesystem::perms::others_exec);
  const pid_t child = ::fork();
  if (child == 0) {
    const passwd* nobody = ::getpwnam("nobody");
    if (::geteuid() == 0 &&
        (nobody == nullptr || ::setgid(nobody->pw_gid) != 0 || ::setuid(nobody->pw_uid) != 0)) {
      ::_exit(3);
    }
    const std::string message = open_error(url);
    const bool one_line = message.find('\n') == std::string::npos;
    ::_exit(message.find("store " + url + ": ") == 0 && one_line ? 0 : 1);
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  std::filesystem::permissions(dir, std::filesystem::perms::owner_all);
  std::filesystem::permissions(
      dir / "fleet.db", std::filesystem::perms::owner_read | std::filesystem::perms::owner_write);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: no one-line StoreError naming the store; 3: no setuid";
  EXPECT_EQ(host::open_store(url)->locomotives().size(), 1u);  // unchanged
}

}  // namespace
}  // namespace flange::testing
