#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Throughput and memory of `flange run` and `flange calibrate` on a 1,000,000-row recording:
#   bash bench/run_bench.sh [FLANGE]     (FLANGE defaults to build/flange)
# Prints samples/s per engine beside the float engine (the baseline, same run), calibration
# time, and the peak memory at 100 k and 1 M rows (flat memory = streaming). seconds are wall
# seconds (what the rate is computed from); CPU s is the process's user + system time, less
# disturbed by other load than the wall seconds.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
flange="${1:-$here/../build/flange}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
coeffs="$here/../coeffs/measurement_sos/filter.json"

"$flange" simulate --scenario bench --seed 9 --duration 166666.5 --out "$work/big.csv" >/dev/null
head -n 100001 "$work/big.csv" >"$work/100k.csv"
"$flange" calibrate --data "$work/100k.csv" --out "$work/model.json" >/dev/null
# Build the RTL runner before timing it.
"$flange" run --input "$work/100k.csv" --calibration "$work/model.json" --coeffs "$coeffs" \
  --engine rtl --out /dev/null >/dev/null 2>&1

measure() {  # label, then the command; prints "label seconds maxrss_kB user_s system_s"
  local label="$1"
  shift
  local start="$EPOCHREALTIME"  # microseconds: /usr/bin/time's %e has only hundredths
  /usr/bin/time -f "%M %U %S" "$@" >/dev/null 2>"$work/time.txt" ||
    { cat "$work/time.txt"; exit 1; }
  local end="$EPOCHREALTIME"
  echo "$label $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }') $(tail -n 1 "$work/time.txt")"
}

rows=1000000
base=$(measure float "$flange" run --input "$work/big.csv" --calibration "$work/model.json" \
  --coeffs "$coeffs" --engine float --out "$work/out.csv")
base_s=$(echo "$base" | awk '{print $2}')
printf '%-28s %10s %12s %8s %10s %8s\n' "what" "seconds" "samples/s" "ratio" "max RSS" "CPU s"
for engine in float model rtl; do
  line=$(measure "$engine" "$flange" run --input "$work/big.csv" --calibration "$work/model.json" \
    --coeffs "$coeffs" --engine "$engine" --out "$work/out.csv")
  s=$(echo "$line" | awk '{print $2}')
  kb=$(echo "$line" | awk '{print $3}')
  cpu=$(echo "$line" | awk '{print $4 + $5}')
  awk -v e="run, engine $engine, 1 M rows" -v s="$s" -v b="$base_s" -v n="$rows" -v kb="$kb" \
    -v cpu="$cpu" 'BEGIN { printf "%-28s %10.3f %12.0f %8.2f %7d kB %8.2f\n", e, s, n / s, s / b, kb, cpu }'
done
small=$(measure model "$flange" run --input "$work/100k.csv" --calibration "$work/model.json" \
  --coeffs "$coeffs" --engine model --out "$work/out.csv")
echo "$small" | awk '{ printf "%-28s %10.3f %12.0f %8s %7d kB %8.2f\n", "run, engine model, 100 k rows", $2, 100000 / $2, "", $3, $4 + $5 }'
cal=$(measure calibrate "$flange" calibrate --data "$work/big.csv" --out "$work/big_model.json")
echo "$cal" | awk '{ printf "%-28s %10.3f %12.0f %8s %7d kB %8.2f\n", "calibrate, 1 M points", $2, 1000000 / $2, "", $3, $4 + $5 }'
