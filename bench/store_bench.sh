#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The store at a national fleet's scale on both backends in one run (docs/benchmarks.md,
# "Store"): a year of a 1,000-locomotive fleet (365,000 runs, 4,380,000 wheel rows and their
# alarm events) into a new database on a PostgreSQL server started for the run with its durable
# defaults (fsync on; a temporary data folder, Unix socket, stopped and deleted before the next
# step), then into a new SQLite file; on each, one wheel's history, the fleet table, `flange
# wear`'s nightly path (every wheel's runs read, the estimate of the first ESTIMATE locomotives'
# wheels, the estimates kept in the store) and the reprofiling plan from the stored estimates
# (checked equal to the plan from the estimate itself), and as the fleet table's baseline the
# read-time aggregate it replaced (bench/store_fleet_aggregate.sql) on the same store. Prints
# two tables.
#
#   bash bench/store_bench.sh [BUILD_DIR] [DAYS (365)] [LOCOMOTIVES (1000)]
#                             [ESTIMATE: PostgreSQL's (all)] [ESTIMATE: SQLite's (100)]
set -euo pipefail
build=${1:-build}
days=${2:-365}
locomotives=${3:-1000}
estimate_pg=${4:-$locomotives}
estimate_sqlite=${5:-$((locomotives < 100 ? locomotives : 100))}
bench=$build/bench/store_bench
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d /tmp/flange_store_bench.XXXXXX)
state=$work/postgres.state
cleanup() {
  bash "$here/../tests/host/store/postgres_server.sh" stop "$state" || true
  rm -rf "$work"
}
trap cleanup EXIT

# Seconds the command takes, its output dropped.
seconds_of() {
  local start end
  start=$(date +%s.%N)
  "$@" >/dev/null
  end=$(date +%s.%N)
  printf "%.2f\n" "$(echo "$end - $start" | bc)"
}

FLANGE_POSTGRES_DURABLE=1 bash "$here/../tests/host/store/postgres_server.sh" start "$state"
socket=$(cat "$state")
psql -q -h "$socket" -U flange -d postgres -c "CREATE DATABASE store_bench" >/dev/null

rows=$work/rows.md
echo "| backend | fleet | runs | wheel rows | alarm rows | ingest s | rows/s in | one wheel's history ms: median (max) | its rows | fleet table ms (wheels) | nightly: runs read s (wheels) | nightly: estimate s (wheels) | nightly: estimates kept s | plan from the stored estimates ms (wheels) | wheels due | size MB |"
echo "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
"$bench" --store "postgresql://flange@/store_bench?host=$socket" --days "$days" \
  --locomotives "$locomotives" --estimate-locomotives "$estimate_pg"
aggregate_pg=$(seconds_of psql -q -h "$socket" -U flange -d store_bench \
  -f "$here/store_fleet_aggregate.sql")
# The server's work is done: stopped before SQLite runs, so that it does not hold memory.
bash "$here/../tests/host/store/postgres_server.sh" stop "$state"
"$bench" --store "sqlite:$work/store_bench.db" --days "$days" --locomotives "$locomotives" \
  --estimate-locomotives "$estimate_sqlite"
aggregate_sqlite=$(seconds_of sqlite3 "$work/store_bench.db" <"$here/store_fleet_aggregate.sql")
echo
echo "| backend | fleet table as the read-time aggregate (baseline), s |"
echo "|---|---:|"
echo "| postgresql | $aggregate_pg |"
echo "| sqlite | $aggregate_sqlite |"
