#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A throwaway PostgreSQL server for the store tests (a CTest fixture runs it; so can a developer).
#
#   bash postgres_server.sh start STATE_FILE   # initdb + pg_ctl start; STATE_FILE gets the folder
#   bash postgres_server.sh stop STATE_FILE    # pg_ctl stop, delete the folder and STATE_FILE
#
# The server listens on a Unix socket in a new folder under /tmp (no TCP port), trusts local
# connections as role "flange" (and role "password_check" only with the password "right", for the
# wrong-password test) and runs without fsync (a test server: nothing to keep);
# FLANGE_POSTGRES_DURABLE=1 keeps PostgreSQL's durable defaults (the benchmark). Debian's
# binaries live in /usr/lib/postgresql/<version>/bin, off PATH. initdb refuses to run as root:
# as root the folder belongs to the "postgres" user and the tools run as it (runuser).
set -euo pipefail

action=${1:?usage: postgres_server.sh start|stop STATE_FILE}
state=${2:?usage: postgres_server.sh start|stop STATE_FILE}

bin=${FLANGE_POSTGRES_BIN:-}
if [ -z "$bin" ]; then
  bin=$(ls -d /usr/lib/postgresql/*/bin 2>/dev/null | sort -V | tail -n 1 || true)
fi
if [ -z "$bin" ] || [ ! -x "$bin/initdb" ]; then
  echo "postgres_server.sh: no PostgreSQL server binaries (install the postgresql package:" \
       "scripts/setup.sh)" >&2
  exit 1
fi

as_owner() {
  if [ "$(id -u)" = 0 ]; then runuser -u postgres -- "$@"; else "$@"; fi
}

case "$action" in
  start)
    folder=$(mktemp -d /tmp/flange_pg.XXXXXX)
    if [ "$(id -u)" = 0 ]; then chown postgres "$folder"; fi
    as_owner "$bin/initdb" -D "$folder/data" -A trust -U flange --no-sync >"$folder/initdb.log" 2>&1 ||
      { cat "$folder/initdb.log" >&2; rm -rf "$folder"; exit 1; }
    # First match wins: the password role's line goes before initdb's "trust" lines.
    hba="$folder/data/pg_hba.conf"
    { echo "local all password_check scram-sha-256"; cat "$hba"; } >"$hba.new"
    mv "$hba.new" "$hba"
    if [ "$(id -u)" = 0 ]; then chown postgres "$hba"; fi
    settings="-k $folder -c listen_addresses=''"
    if [ "${FLANGE_POSTGRES_DURABLE:-0}" != 1 ]; then
      settings+=" -c fsync=off -c synchronous_commit=off -c full_page_writes=off"
    fi
    as_owner "$bin/pg_ctl" -D "$folder/data" -l "$folder/server.log" -w -t 60 -o "$settings" \
      start >/dev/null ||
      { cat "$folder/server.log" >&2; rm -rf "$folder"; exit 1; }
    psql -q -h "$folder" -U flange -d postgres \
      -c "CREATE ROLE password_check LOGIN SUPERUSER PASSWORD 'right'" >/dev/null
    mkdir -p "$(dirname "$state")"
    echo "$folder" >"$state"
    ;;
  stop)
    [ -f "$state" ] || exit 0
    folder=$(cat "$state")
    if [ -d "$folder/data" ]; then
      as_owner "$bin/pg_ctl" -D "$folder/data" -m immediate -w stop >/dev/null 2>&1 || true
    fi
    case "$folder" in /tmp/flange_pg.*) rm -rf "$folder" ;; esac
    rm -f "$state"
    ;;
  *)
    echo "postgres_server.sh: unknown action $action (start or stop)" >&2
    exit 2
    ;;
esac
