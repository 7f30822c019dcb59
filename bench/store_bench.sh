#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The store at a national fleet's scale on both backends in one run (docs/benchmarks.md,
# "Store"): a year of a 1,000-locomotive fleet (365,000 runs, 4,380,000 wheel rows and their
# alarm events) into a new SQLite file and into a new database on a PostgreSQL server started
# for the run with its durable defaults (fsync on; a temporary data folder, Unix socket, stopped
# and deleted at the end), then one wheel's history, the fleet table and the reprofiling plan
# (the store's read of every wheel's runs on both; the estimate and plan, which do not touch the
# store, of the first 100 locomotives after the PostgreSQL read). Prints a table.
#
#   bash bench/store_bench.sh [BUILD_DIR] [DAYS (365)] [LOCOMOTIVES (1000)]
set -euo pipefail
build=${1:-build}
days=${2:-365}
locomotives=${3:-1000}
bench=$build/bench/store_bench
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d /tmp/flange_store_bench.XXXXXX)
state=$work/postgres.state
cleanup() {
  bash "$here/../tests/host/store/postgres_server.sh" stop "$state" || true
  rm -rf "$work"
}
trap cleanup EXIT

FLANGE_POSTGRES_DURABLE=1 bash "$here/../tests/host/store/postgres_server.sh" start "$state"
socket=$(cat "$state")
psql -q -h "$socket" -U flange -d postgres -c "CREATE DATABASE store_bench" >/dev/null

echo "| backend | fleet | runs | wheel rows | alarm rows | ingest s | rows/s in | one wheel's history ms: median (max) | its rows | fleet table ms (wheels) | plan: store read s (wheels) | plan: estimate and plan s (wheels) | wheels due | size MB |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
"$bench" --store "sqlite:$work/store_bench.db" --days "$days" --locomotives "$locomotives" \
  --estimate-locomotives 0
rm -f "$work"/store_bench.db*
"$bench" --store "postgresql://flange@/store_bench?host=$socket" --days "$days" \
  --locomotives "$locomotives" --estimate-locomotives "$((locomotives < 100 ? locomotives : 100))"
