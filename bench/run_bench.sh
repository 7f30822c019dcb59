#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Throughput and memory of `flange run` and `flange calibrate` on a 1,000,000-row recording:
#   bash bench/run_bench.sh [FLANGE]     (FLANGE defaults to build/flange)
# Prints samples/s per engine beside the float engine (the baseline, same run), calibration
# time, and the peak memory at 100 k and 1 M rows (flat memory = streaming). seconds are wall
# seconds (what the rate is computed from); CPU s is the process's user + system time, less
# disturbed by other load than the wall seconds. The float and model engines' 1 M-row runs are
# the median of REPEAT runs (default 5; fastest and slowest in the last column), taken in turn.
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
  # The runs before wrote 45 MB each: flushed now, not by the kernel's writeback under this one.
  sync
  local start="$EPOCHREALTIME"  # microseconds: /usr/bin/time's %e has only hundredths
  /usr/bin/time -f "%M %U %S" "$@" >/dev/null 2>"$work/time.txt" ||
    { cat "$work/time.txt"; exit 1; }
  local end="$EPOCHREALTIME"
  echo "$label $(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }') $(tail -n 1 "$work/time.txt")"
}

rows=1000000
repeat="${REPEAT:-5}"
run_engine() {  # engine: one timed run of it on the 1 M-row recording
  measure "$1" "$flange" run --input "$work/big.csv" --calibration "$work/model.json" \
    --coeffs "$coeffs" --engine "$1" --out "$work/out.csv"
}
# The float and model engines in turn, so that both see the same spells of other load.
for ((k = 0; k < repeat; ++k)); do
  run_engine float >>"$work/float.txt"
  run_engine model >>"$work/model.txt"
done
run_engine rtl >"$work/rtl.txt"
median_line() { sort -k2,2n "$1" | awk -v n="$(wc -l <"$1")" 'NR == int((n + 1) / 2)'; }
base_s=$(median_line "$work/float.txt" | awk '{print $2}')
printf '%-28s %10s %12s %8s %10s %8s  %s\n' "what" "seconds" "samples/s" "ratio" "max RSS" "CPU s" \
  "fastest-slowest of $repeat"
for engine in float model rtl; do
  line=$(median_line "$work/$engine.txt")
  spread=$(sort -k2,2n "$work/$engine.txt" | awk 'NR == 1 { a = $2 } { b = $2 } END { if (NR > 1) printf "%.3f-%.3f", a, b }')
  s=$(echo "$line" | awk '{print $2}')
  kb=$(echo "$line" | awk '{print $3}')
  cpu=$(echo "$line" | awk '{print $4 + $5}')
  awk -v e="run, engine $engine, 1 M rows" -v s="$s" -v b="$base_s" -v n="$rows" -v kb="$kb" \
    -v cpu="$cpu" -v spread="$spread" \
    'BEGIN { printf "%-28s %10.3f %12.0f %8.2f %7d kB %8.2f  %s\n", e, s, n / s, s / b, kb, cpu, spread }'
done
small=$(measure model "$flange" run --input "$work/100k.csv" --calibration "$work/model.json" \
  --coeffs "$coeffs" --engine model --out "$work/out.csv")
echo "$small" | awk '{ printf "%-28s %10.3f %12.0f %8s %7d kB %8.2f\n", "run, engine model, 100 k rows", $2, 100000 / $2, "", $3, $4 + $5 }'
cal=$(measure calibrate "$flange" calibrate --data "$work/big.csv" --out "$work/big_model.json")
echo "$cal" | awk '{ printf "%-28s %10.3f %12.0f %8s %7d kB %8.2f\n", "calibrate, 1 M points", $2, 1000000 / $2, "", $3, $4 + $5 }'
