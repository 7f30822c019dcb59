// SPDX-License-Identifier: MIT
// Rows of one table gathered as columns and written with one statement: on PostgreSQL an
// INSERT ... SELECT FROM unnest() of one array parameter per column (one round trip for the
// whole batch instead of one per row); on SQLite SOCI's bulk binding (in-process, no round
// trips). Values travel as bound parameters either way. A non-finite number is written as NULL.
#pragma once

#include <soci/soci.h>

#include <optional>
#include <string>
#include <vector>

#include "store_url.h"

namespace flange::host {

class ColumnBatch {
 public:
  // `columns`: name and PostgreSQL type of each column, e.g. {"run_id", "BIGINT"}.
  ColumnBatch(std::string table, std::vector<std::pair<std::string, std::string>> columns);

  // One row's values, in the order of the columns; call once per column.
  void add(long long value);
  void add(double value);
  void add(const std::optional<double>& value);
  void add(const std::optional<long long>& value);
  void add(const std::string& value);

  std::size_t rows() const;
  // Writes the rows gathered and empties the batch.
  void flush(soci::session& sql, StoreBackend backend);
  // PostgreSQL only: the same for a table with an identity column `id`, returning the new ids
  // in the order the rows were added.
  std::vector<long long> flush_returning_ids(soci::session& sql);

 private:
  void add_text(std::optional<std::string> value);
  void flush_postgresql(soci::session& sql);
  // The INSERT ... SELECT FROM unnest() text; its parameters bound to `literals`.
  std::string postgresql_insert(std::vector<std::string>& literals) const;
  void clear();
  void flush_sqlite(soci::session& sql);

  std::string table_;
  std::vector<std::pair<std::string, std::string>> columns_;
  std::vector<std::vector<std::string>> values_;       // per column
  std::vector<std::vector<soci::indicator>> present_;  // per column
  std::size_t next_column_ = 0;
};

}  // namespace flange::host
