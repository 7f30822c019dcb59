#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# How soon `flange wear` flags a drifting sensor, and whether the flag stays (docs/fleet.md, "How
# soon a drift is flagged"): for each fleet bench/wear_coverage.sh left in build/wear_coverage/,
# the depot's estimate run weekly as it would run it after its ingest. One copy of the store per
# cut date (every 7 days, aligned on the fleet's first drift start, from two weeks after the
# first day to the end), the runs and maintenance from the cut on deleted, with the wear
# estimates (and so the sensor flags, host/wear/sensor_flag_latch.h) the previous cut's
# `flange wear` kept, read by `flange wear` (the copies are made in the fleet's folder, under
# cuts/, and deleted as it goes). Prints, for each drifting sensor, the days from its
# start to the first cut whose search flags it and to the first whose flag is latched, and
# whether it is flagged at the end (the search alone; the search or the latch); for the healthy
# sensors, how many the search flags at some cut, how many are ever latched and how many are
# flagged at the end.
#   bash bench/wear_drift_delay.sh [LOCOMOTIVES] [DAYS] [FLANGE] [REALITY] [FOLDER]
#   (defaults: 5, 90, build/flange, fleet, build/wear_coverage)
# Run bench/wear_coverage.sh (REALITY fleet) or bench/wear_coverage_alt.sh (REALITY fleet-alt: the
# stores the service path filled) with the same LOCOMOTIVES and DAYS first.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
locomotives="${1:-5}"
days="${2:-90}"
flange="${3:-$here/../build/flange}"
reality="${4:-fleet}"
out="${5:-$here/../build/wear_coverage}"
case "$reality" in
  fleet) prefix=seed; db=fleet.db; truth=fleet_truth.json ;;
  fleet-alt) prefix=alt_seed; db=store.db; truth=depot/fleet_truth.json ;;
  *) echo "REALITY: $reality is neither fleet nor fleet-alt" >&2; exit 2 ;;
esac
python3 "$here/wear_drift_delay.py" "$out" "${locomotives}x${days}" "$flange" "$prefix" "$db" \
  "$truth"
