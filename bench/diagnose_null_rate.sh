#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# How often `flange diagnose` says "none" on pairs with no effect (docs/diagnose.md, "Null
# pairs"; issue 11 item 3 asks for >= 99 % at any noise from 0.005 to 0.15 V, 6 Hz or 100 Hz).
# Each draw: two bench sessions of the twin with the given white noise and nothing else, seeds
# SEED + 2i and SEED + 2i + 1 (another noise draw, another session), diagnosed as
# `flange diagnose --real A --holdout B` reads them. Prints one row per noise level, with every
# draw that was not "none" and what it named. With STARTS_APART_H=H the sessions are given start
# times (--real-start, --holdout-start) H hours apart, so the ageing's held-out choices run too;
# without, the clocks are unknown.
#   bash bench/diagnose_null_rate.sh FS_HZ DURATION_S DRAWS SEED NOISE_V...
#     [FLANGE=build/flange] [STARTS_APART_H=16]
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
flange="${FLANGE:-$root/build/flange}"
if (($# < 5)); then
  echo "usage: bash bench/diagnose_null_rate.sh FS_HZ DURATION_S DRAWS SEED NOISE_V..." >&2
  exit 2
fi
fs="$1" duration="$2" draws="$3" seed="$4"
shift 4
starts=()
if [[ -n "${STARTS_APART_H:-}" ]]; then
  later=$(date -u -d "2026-01-01T00:00:00Z + ${STARTS_APART_H} hours" +%Y-%m-%dT%H:%M:%SZ)
  starts=(--real-start 2026-01-01T00:00:00Z --holdout-start "$later")
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
"$flange" simulate --scenario bench --seed 1 --duration 600 --out "$work/x.csv" \
  --save-twin "$work/default_twin.json" > /dev/null
printf '| fs | session | noise | draws | "none" | not "none" (seed: verdict) | seconds per draw |\n'
printf '|---|---|---|---|---|---|---|\n'
for noise in "$@"; do
  sed "s/\"voltage_std_v\": [0-9.e-]*/\"voltage_std_v\": $noise/" "$work/default_twin.json" \
    > "$work/twin.json"
  none=0 others="" start=$(date +%s.%N)
  for ((i = 0; i < draws; i++)); do
    s=$((seed + 2 * i))
    for part in 0 1; do
      "$flange" simulate --scenario bench --fs "$fs" --duration "$duration" --seed $((s + part)) \
        --twin "$work/twin.json" --out "$work/$part.csv" > /dev/null
    done
    verdict=$("$flange" diagnose --real "$work/0.csv" --holdout "$work/1.csv" "${starts[@]}" \
      --out "$work/d" | head -n 1)
    if [[ "$verdict" == "verdict: none" ]]; then
      none=$((none + 1))
    else
      others="$others $s: ${verdict#verdict: };"
    fi
  done
  per=$(echo "$start $(date +%s.%N) $draws" | awk '{printf "%.1f", ($2 - $1) / $3}')
  printf '| %s Hz | %s s | %s V | %s | %s | %s | %s |\n' "$fs" "$duration" "$noise" "$draws" \
    "$none" "${others:- -}" "$per"
done
