#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A depot's folder through the service path into a store, as the depot would feed it: the bench
# sessions into `flange calibrate --store` (one calibration fitted on all of them), the depot's
# maintenance records into `flange maintenance`, then every locomotive-day's manifest into
# `flange run --manifest --store` with its date, distance and odometer, in time order.
# The folder is what `flange simulate --scenario fleet-alt --out DIR` writes (docs/fleet.md).
# Usage: fleet_service.sh FLANGE DIR STORE_URL [COEFFS]
#   COEFFS: the filter (default coeffs/measurement_sos/filter.json of this checkout).
set -euo pipefail
flange=${1:?path of the flange executable}
dir=${2:?the folder flange simulate --scenario fleet-alt wrote}
store=${3:?sqlite:PATH or postgresql://...}
coeffs=${4:-$(cd "$(dirname "$0")/.." && pwd)/coeffs/measurement_sos/filter.json}
model=$dir/model.json

for bench in "$dir"/bench/bench_*.csv; do
  "$flange" calibrate --store "$store" --append "$bench" --out "$model" > /dev/null
done

events=0
while IFS=, read -r at locomotive axle side kind odometer from_axle sensor; do
  args=(maintenance --store "$store" --locomotive "$locomotive" --kind "$kind" --at "$at"
        --odometer-km "$odometer")
  [ -n "$axle" ] && args+=(--axle "$axle")
  [ -n "$side" ] && args+=(--side "$side")
  [ -n "$from_axle" ] && args+=(--from-axle "$from_axle")
  [ -n "$sensor" ] && args+=(--sensor "$sensor")
  "$flange" "${args[@]}" > /dev/null
  events=$((events + 1))
done < <(tail -n +2 "$dir/maintenance.csv")

runs=0
while IFS=, read -r started_at locomotive manifest distance_km odometer_km; do
  "$flange" run --manifest "$dir/$manifest" --calibration "$model" --coeffs "$coeffs" \
    --store "$store" --locomotive "$locomotive" --started-at "$started_at" \
    --distance-km "$distance_km" --odometer-km "$odometer_km" > /dev/null
  runs=$((runs + 1))
done < <(tail -n +2 "$dir/runs.csv")
echo "fleet_service: $events maintenance records and $runs locomotive runs into $store"
