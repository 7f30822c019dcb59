// SPDX-License-Identifier: MIT
#include "store_url.h"

#include <libpq-fe.h>

#include <memory>
#include <regex>

#include "input_error.h"
#include "store.h"

namespace flange::host {

namespace {

constexpr const char* kForms = "sqlite:PATH or postgresql://[USER[:PASSWORD]@][HOST][:PORT]/DBNAME";

// "postgresql://user:secret@host/db?password=x" -> "postgresql://user:***@host/db?password=***".
std::string masked(const std::string& url) {
  static const std::regex user_password(R"((://[^:/@?]*):[^@/?]*@)");
  static const std::regex query_password(R"(([?&]password=)[^&]*)");
  return std::regex_replace(std::regex_replace(url, user_password, "$1:***@"), query_password,
                            "$1***");
}

[[noreturn]] void refuse(const std::string& shown, const std::string& why) {
  throw StoreUrlError("store " + printable_excerpt(shown, 120) + ": " + why + " (use " + kForms +
                      ")");
}

// libpq parses its own URIs; a URI it cannot parse is a bad argument, found before connecting.
void check_postgresql_uri(const std::string& url, const std::string& shown) {
  char* message = nullptr;
  PQconninfoOption* options = PQconninfoParse(url.c_str(), &message);
  std::unique_ptr<char, decltype(&PQfreemem)> message_owner(message, &PQfreemem);
  if (options == nullptr) {
    std::string why = message ? message : "not a PostgreSQL URI";
    while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
    refuse(shown, why);
  }
  std::string dbname;
  for (PQconninfoOption* option = options; option->keyword != nullptr; ++option) {
    if (std::string(option->keyword) == "dbname" && option->val != nullptr) dbname = option->val;
  }
  PQconninfoFree(options);
  if (dbname.empty()) refuse(shown, "no database name");
}

}  // namespace

StoreUrl parse_store_url(const std::string& url) {
  StoreUrl parsed;
  parsed.shown = masked(url);
  if (url.rfind("sqlite:", 0) == 0) {
    parsed.backend = StoreBackend::kSqlite;
    parsed.target = url.substr(7);
    if (parsed.target.rfind("//", 0) == 0) parsed.target = parsed.target.substr(2);
    if (parsed.target.empty()) refuse(parsed.shown, "no file path");
    if (parsed.target.find('\0') != std::string::npos) refuse(parsed.shown, "a NUL in the path");
    return parsed;
  }
  if (url.rfind("postgresql://", 0) == 0 || url.rfind("postgres://", 0) == 0) {
    parsed.backend = StoreBackend::kPostgresql;
    parsed.target = url;
    check_postgresql_uri(url, parsed.shown);
    return parsed;
  }
  refuse(parsed.shown, "unknown kind of store");
}

}  // namespace flange::host
