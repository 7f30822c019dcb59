#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# How often `flange wear`'s intervals hold the truth (docs/fleet.md, "How often the intervals
# hold"): fleets simulated from seeds the method was never fitted on, each read back by
# `flange wear --truth`, and the per-wheel checks pooled into one table by wheel kind (healthy,
# reprofiled, drifting sensor) for the rate and the dates of the warning and critical limits, at
# 95 % and 80 %, each share with its 90 % range from a bootstrap over whole locomotives (whose
# wheels share their km per day); then the rate, reprofiling and drift checks summed over the
# fleets (bench/wear_coverage_table.py). bench/wear_coverage_alt.sh does the same on the second reality.
#   bash bench/wear_coverage.sh [SEEDS] [LOCOMOTIVES] [DAYS] [FLANGE]
#   (defaults: "9101 9102 9103 9104 9105", 5, 90, build/flange: 300 wheels)
# Leaves every seed's store, wear outputs and truth_check.json in
# build/wear_coverage/seed_S_LxD/. A seed whose store and truth file are already there (from an
# earlier run with the same locomotives and days) is not simulated again: the simulation is
# deterministic in its seed, so only `flange wear` runs anew. The store keeps each run's
# clearance as it was worked out when stored: delete the folder after changing that.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=bench/wear_truth_check.sh
source "$here/wear_truth_check.sh"
seeds="${1:-9101 9102 9103 9104 9105}"
locomotives="${2:-5}"
days="${3:-90}"
flange="${4:-$here/../build/flange}"
out="$here/../build/wear_coverage"
mkdir -p "$out"
checks=()
for seed in $seeds; do
  dir="$out/seed_${seed}_${locomotives}x${days}"
  if [ ! -f "$dir/fleet_truth.json" ] || [ ! -f "$dir/fleet.db" ]; then
    rm -rf "$dir"
    mkdir -p "$dir"
    "$flange" simulate --scenario fleet --locomotives "$locomotives" --days "$days" \
      --seed "$seed" --store "sqlite:$dir/fleet.db" > "$dir/simulate.log"
  fi
  wear_truth_check "$flange" "sqlite:$dir/fleet.db" "$dir/fleet_truth.json" "$dir" "$seed"
  checks+=("$dir/wear/truth_check.json")
done
python3 "$here/wear_coverage_table.py" "${checks[@]}"
