// SPDX-License-Identifier: MIT
// One write transaction, rolled back unless committed. SQLite's is BEGIN IMMEDIATE: the write
// lock is taken at the start, so two writers queue on the busy timeout instead of one failing
// when it upgrades a read lock.
#pragma once

#include <soci/soci.h>

#include "store_url.h"

namespace flange::host {

class WriteTransaction {
 public:
  WriteTransaction(soci::session& sql, StoreBackend backend) : sql_(sql) {
    sql_ << (backend == StoreBackend::kSqlite ? "BEGIN IMMEDIATE" : "BEGIN");
  }
  WriteTransaction(const WriteTransaction&) = delete;
  WriteTransaction& operator=(const WriteTransaction&) = delete;
  ~WriteTransaction() {
    if (open_) {
      try {
        sql_ << "ROLLBACK";
      } catch (...) {  // a lost connection rolls back on the server's side
      }
    }
  }
  void commit() {
    sql_ << "COMMIT";
    open_ = false;
  }

 private:
  soci::session& sql_;
  bool open_ = true;
};

}  // namespace flange::host
