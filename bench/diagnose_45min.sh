#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A 45-minute pair must diagnose in under 5 s on 2 cores (the 6 Hz ones under 1 s), in under
# 1 GB. Times `flange diagnose --real A --holdout B` on pairs of bench sessions (2700 s, seeds 31
# and 32), one row per pair:
#   lag    a thermal lag of 300 s, at 6 Hz and at 100 Hz (explained: the library pass ends it)
#   step   the lag pair with the voltage x 1.04 from half-way in both sessions (a gain step
#          outside the library: the free-shape pass runs every family, the slowest path)
#   mains  100 Hz, mains pickup of 0.1 V at 60 Hz (its line and harmonics alias to 40 and 20 Hz)
#   two    100 Hz, the lag and a gain drifting with temperature (two library picks)
# With a second binary (the one before a change) each pair is diagnosed by both, one after the
# other, so that both meet the same load; the last column says whether their diagnosis.json
# files agree (but for the command line that made them).
#
#   bash bench/diagnose_45min.sh [build dir] [work dir] [baseline flange]
set -euo pipefail
build=${1:-build}
work=${2:-$build/diagnose_45min}
baseline=${3:-}
flange=$build/flange
mkdir -p "$work"
[ -z "$baseline" ] || [ -x "$baseline" ] ||
  { echo "diagnose_45min.sh: $baseline is not an executable" >&2; exit 2; }

# The voltage column times 1.04 from the middle row on (header lines kept).
gain_step() {
  awk -F, -v OFS=, 'NR == FNR { if ($1 ~ /^[0-9.]+$/) rows++; next }
    $1 !~ /^[0-9.]+$/ { print; next }
    { if (++row > rows / 2) $4 = sprintf("%.6f", $4 * 1.04); print }' "$1" "$1" >"$2"
}

# simulate NAME FS EFFECT...: the pair NAME_FS_31.csv and NAME_FS_32.csv.
simulate() {
  local name=$1 fs=$2 seed
  shift 2
  local effects=()
  for e in "$@"; do effects+=(--effect "$e"); done
  for seed in 31 32; do
    "$flange" simulate --scenario bench --duration 2700 --fs "$fs" --seed "$seed" "${effects[@]}" \
      --out "$work/${name}_${fs}_$seed.csv" >/dev/null
  done
}

# diagnose BINARY PAIR FS OUT: "wall user peak_mb" of one diagnosis into OUT/.
diagnose() {
  local timing
  timing=$( { /usr/bin/time -f "%e %U %M" "$1" diagnose --real "$work/${2}_${3}_31.csv" \
    --holdout "$work/${2}_${3}_32.csv" --out "$4" >"$4.txt"; } 2>&1 | tail -1)
  read -r wall user kb <<<"$timing"
  echo "$wall $user $((kb / 1024))"
}

# The diagnosis.json without the command lines that made it (its binary's path).
decided() { grep -v '"generated_by"' "$1/diagnosis.json"; }

lag=thermal_lag:tau_s=300
if [ -n "$baseline" ]; then
  echo "| fs | pair | verdict | wall s | user s | peak MB | before: wall s | user s | peak MB | same diagnosis |"
  echo "|---|---|---|---:|---:|---:|---:|---:|---:|---|"
else
  echo "| fs | pair | verdict | wall s | user s | peak MB |"
  echo "|---|---|---|---:|---:|---:|"
fi
for fs in 6 100; do
  simulate lag "$fs" "$lag"
  for seed in 31 32; do gain_step "$work/lag_${fs}_$seed.csv" "$work/step_${fs}_$seed.csv"; done
  pairs="lag step"
  if [ "$fs" = 100 ]; then
    simulate mains "$fs" mains_pickup:mains_hz=60,amplitude_v=0.1
    simulate two "$fs" "$lag" temp_gain_drift
    pairs="lag step mains two"
  fi
  for pair in $pairs; do
    out=$work/out_${pair}_$fs
    read -r wall user mb <<<"$(diagnose "$flange" "$pair" "$fs" "$out")"
    verdict=$(head -1 "$out.txt" | sed 's/^verdict: //')
    row="| $fs Hz | $pair | $verdict | $wall | $user | $mb |"
    if [ -n "$baseline" ]; then
      read -r b_wall b_user b_mb <<<"$(diagnose "$baseline" "$pair" "$fs" "$out.before")"
      same=no
      cmp -s <(decided "$out") <(decided "$out.before") && same=yes
      row="$row $b_wall | $b_user | $b_mb | $same |"
    fi
    echo "$row"
  done
done
echo "(load average: $(cut -d' ' -f1-3 /proc/loadavg); $(nproc) cores)"
