#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# bench/wear_coverage.sh on the second fleet reality (sim/fleet_alt, docs/fleet.md): fleets
# simulated by `flange simulate --scenario fleet-alt` from seeds the method was never set on, fed
# through the service path (scripts/fleet_service.sh: `flange calibrate --store`, `flange
# maintenance`, `flange run --manifest --store` for every locomotive-day), read back by `flange
# wear --truth`, and pooled into the same table by wheel kind (bench/wear_coverage_table.py).
#   bash bench/wear_coverage_alt.sh [SEEDS] [LOCOMOTIVES] [DAYS] [FLANGE]
#   (defaults: "9241 9242 9243 9244 9245", 5, 120, build/flange: 300 wheels)
# Leaves every seed's depot folder, store and wear outputs in
# build/wear_coverage/alt_seed_S_LxD/; a seed whose store is complete there (from an earlier run
# of the same binary) is not simulated or fed again: delete the folder after changing how a run
# is stored.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
# shellcheck source=bench/wear_truth_check.sh
source "$here/wear_truth_check.sh"
seeds="${1:-9241 9242 9243 9244 9245}"
locomotives="${2:-5}"
days="${3:-120}"
flange="${4:-$here/../build/flange}"
out="$here/../build/wear_coverage"
mkdir -p "$out"
checks=()
for seed in $seeds; do
  dir="$out/alt_seed_${seed}_${locomotives}x${days}"
  if [ ! -f "$dir/stored" ]; then
    rm -rf "$dir"
    mkdir -p "$dir"
    "$flange" simulate --scenario fleet-alt --locomotives "$locomotives" --days "$days" \
      --seed "$seed" --out "$dir/depot" > "$dir/simulate.log"
    bash "$here/../scripts/fleet_service.sh" "$flange" "$dir/depot" "sqlite:$dir/store.db" \
      > "$dir/service.log"
    rm -rf "$dir/depot/days"  # the recordings: the store keeps what `flange wear` reads
    touch "$dir/stored"
  fi
  wear_truth_check "$flange" "sqlite:$dir/store.db" "$dir/depot/fleet_truth.json" "$dir" "$seed"
  checks+=("$dir/wear/truth_check.json")
done
python3 "$here/wear_coverage_table.py" "${checks[@]}"
