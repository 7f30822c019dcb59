// SPDX-License-Identifier: MIT
#include "column_batch.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace flange::host {

namespace {

// An element of a PostgreSQL array literal: quoted, with " and \ escaped; NULL unquoted.
void append_element(std::string& literal, const std::string& value, soci::indicator present) {
  if (literal.size() > 1) literal += ',';
  if (present != soci::i_ok) {
    literal += "NULL";
    return;
  }
  literal += '"';
  for (const char c : value) {
    if (c == '"' || c == '\\') literal += '\\';
    literal += c;
  }
  literal += '"';
}

}  // namespace

ColumnBatch::ColumnBatch(std::string table,
                         std::vector<std::pair<std::string, std::string>> columns)
    : table_(std::move(table)),
      columns_(std::move(columns)),
      values_(columns_.size()),
      present_(columns_.size()) {}

void ColumnBatch::add_text(std::optional<std::string> value) {
  present_[next_column_].push_back(value ? soci::i_ok : soci::i_null);
  values_[next_column_].push_back(value ? std::move(*value) : std::string());
  next_column_ = (next_column_ + 1) % columns_.size();
}

void ColumnBatch::add(long long value) { add_text(std::to_string(value)); }

void ColumnBatch::add(double value) {
  // fmt's shortest form reads back to the same double.
  add_text(std::isfinite(value) ? std::optional(fmt::format("{}", value)) : std::nullopt);
}

void ColumnBatch::add(const std::optional<double>& value) {
  if (value) {
    add(*value);
  } else {
    add_text(std::nullopt);
  }
}

void ColumnBatch::add(const std::optional<long long>& value) {
  add_text(value ? std::optional(std::to_string(*value)) : std::nullopt);
}

void ColumnBatch::add(const std::string& value) { add_text(value); }

std::size_t ColumnBatch::rows() const { return values_.empty() ? 0 : values_.back().size(); }

void ColumnBatch::clear() {
  for (auto& column : values_) column.clear();
  for (auto& column : present_) column.clear();
}

void ColumnBatch::flush(soci::session& sql, StoreBackend backend) {
  if (rows() == 0) return;
  if (backend == StoreBackend::kPostgresql) {
    flush_postgresql(sql);
  } else {
    flush_sqlite(sql);
  }
  clear();
}

std::string ColumnBatch::postgresql_insert(std::vector<std::string>& literals) const {
  literals.assign(columns_.size(), std::string());
  std::string names, arrays;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    std::string& literal = literals[c];
    literal.push_back('{');
    for (std::size_t r = 0; r < values_[c].size(); ++r) {
      append_element(literal, values_[c][r], present_[c][r]);
    }
    literal += '}';
    if (c > 0) names += ", ";
    names += columns_[c].first;
    arrays += fmt::format("{}CAST(:c{} AS {}[])", c ? ", " : "", c, columns_[c].second);
  }
  // WITH ORDINALITY ... ORDER BY: the rows go in (and take their ids) in the order added.
  return fmt::format(
      "INSERT INTO {0} ({1}) SELECT {1} FROM unnest({2}) WITH ORDINALITY AS u ({1}, ordinal)"
      " ORDER BY ordinal",
      table_, names, arrays);
}

void ColumnBatch::flush_postgresql(soci::session& sql) {
  std::vector<std::string> literals;
  const std::string text = postgresql_insert(literals);
  soci::statement insert(sql);
  for (std::string& literal : literals) insert.exchange(soci::use(literal));
  insert.alloc();
  insert.prepare(text);
  insert.define_and_bind();
  insert.execute(true);
}

std::vector<long long> ColumnBatch::flush_returning_ids(soci::session& sql) {
  std::vector<long long> ids(rows());
  if (ids.empty()) return ids;
  std::vector<std::string> literals;
  const std::string text = postgresql_insert(literals) + " RETURNING id";
  soci::statement insert(sql);
  for (std::string& literal : literals) insert.exchange(soci::use(literal));
  insert.exchange(soci::into(ids));
  insert.alloc();
  insert.prepare(text);
  insert.define_and_bind();
  insert.execute(true);
  // Identity values are drawn row by row in insertion order, so ascending ids are the rows in
  // the order added, whatever order RETURNING lists them in.
  std::sort(ids.begin(), ids.end());
  clear();
  return ids;
}

void ColumnBatch::flush_sqlite(soci::session& sql) {
  std::string names, placeholders;
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    if (c > 0) names += ", ";
    names += columns_[c].first;
    placeholders += fmt::format("{}:c{}", c ? ", " : "", c);
  }
  soci::statement insert(sql);
  for (std::size_t c = 0; c < columns_.size(); ++c) {
    insert.exchange(soci::use(values_[c], present_[c]));
  }
  insert.alloc();
  insert.prepare(fmt::format("INSERT INTO {} ({}) VALUES ({})", table_, names, placeholders));
  insert.define_and_bind();
  insert.execute(true);
}

}  // namespace flange::host
