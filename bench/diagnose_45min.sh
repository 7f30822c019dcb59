#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A 45-minute pair must diagnose in under 10 s on 2 cores. Times
# `flange diagnose --real A --holdout B` on four pairs of bench sessions (2700 s, a thermal lag
# of 300 s), at 6 Hz and at 100 Hz, each as made (explained: the library pass ends it) and with
# the voltage x 1.04 from half-way in both sessions (a gain step outside the library: the
# free-shape pass runs every family, the slowest path). Prints one row per pair.
#
#   bash bench/diagnose_45min.sh [build dir] [work dir]
set -euo pipefail
build=${1:-build}
work=${2:-$build/diagnose_45min}
flange=$build/flange
mkdir -p "$work"

# The voltage column times 1.04 from the middle row on (header lines kept).
gain_step() {
  awk -F, -v OFS=, 'NR == FNR { if ($1 ~ /^[0-9.]+$/) rows++; next }
    $1 !~ /^[0-9.]+$/ { print; next }
    { if (++row > rows / 2) $4 = sprintf("%.6f", $4 * 1.04); print }' "$1" "$1" >"$2"
}

echo "| fs | pair | verdict | wall s | user s |"
echo "|---|---|---|---:|---:|"
for fs in 6 100; do
  for seed in 31 32; do
    "$flange" simulate --scenario bench --duration 2700 --fs "$fs" --seed "$seed" \
      --effect thermal_lag:tau_s=300 --out "$work/lag_${fs}_$seed.csv" >/dev/null
    gain_step "$work/lag_${fs}_$seed.csv" "$work/step_${fs}_$seed.csv"
  done
  for pair in lag step; do
    out=$work/out_${pair}_$fs
    timing=$( { /usr/bin/time -f "%e %U" "$flange" diagnose --real "$work/${pair}_${fs}_31.csv" \
      --holdout "$work/${pair}_${fs}_32.csv" --out "$out" >"$out.txt"; } 2>&1 | tail -1)
    verdict=$(head -1 "$out.txt" | sed 's/^verdict: //')
    echo "| $fs Hz | $pair | $verdict | ${timing% *} | ${timing#* } |"
  done
done
echo "(load average: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores)"
