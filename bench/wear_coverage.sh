#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# How often `flange wear`'s intervals hold the truth (docs/fleet.md, "How often the intervals
# hold"): fleets simulated from seeds the method was never fitted on, each read back by
# `flange wear --truth`, and the per-wheel checks pooled into one table by wheel kind (healthy,
# reprofiled, drifting sensor) for the rate and the dates of the warning and critical limits, at
# 95 % and 80 %; then the rate, reprofiling and drift checks summed over the fleets.
#   bash bench/wear_coverage.sh [SEEDS] [LOCOMOTIVES] [DAYS] [FLANGE]
#   (defaults: "9101 9102 9103 9104 9105", 5, 90, build/flange: 300 wheels)
# Leaves every seed's store, wear outputs and truth_check.json in
# build/wear_coverage/seed_S_LxD/. A seed whose store and truth file are already there (from an
# earlier run with the same locomotives and days) is not simulated again: the simulation is
# deterministic in its seed, so only `flange wear` runs anew.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
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
  rm -rf "$dir/wear"
  # Exit status 1 is a failed check against the truth: counted below, not fatal here.
  status=0
  "$flange" wear --store "sqlite:$dir/fleet.db" --out "$dir/wear" \
    --truth "$dir/fleet_truth.json" > "$dir/wear.log" || status=$?
  if [ "$status" -gt 1 ]; then
    echo "flange wear failed on seed $seed (exit $status): $dir/wear.log" >&2
    exit "$status"
  fi
  echo "seed $seed: $(grep '^verdict' "$dir/wear.log")"
  checks+=("$dir/wear/truth_check.json")
done
python3 - "${checks[@]}" <<'PY'
import json, os, statistics, sys

checks = [json.load(open(path)) for path in sys.argv[1:]]
estimates = [json.load(open(os.path.join(os.path.dirname(path), "wear.json")))
             for path in sys.argv[1:]]
wheels = [w for c in checks for w in c["wheels"]]
kinds = ["healthy", "reprofiled", "drifting sensor", "all"]
quantities = [("rate", "rate_coverage"), ("warning date", "warning_coverage"),
              ("critical date", "critical_coverage")]
print(f"\n{len(checks)} fleets, {len(wheels)} wheels\n")
print("| wheels | interval of | checked | holds the truth at 95 % | at 80 % |")
print("|---|---|---|---|---|")
for kind in kinds:
    chosen = [w for w in wheels if kind == "all" or w["kind"] == kind]
    for name, field in quantities:
        known = [w[field] for w in chosen if w[field] is not None]
        if not known:
            print(f"| {kind} | {name} | 0 | - | - |")
            continue
        cells = []
        for level in ("95", "80"):
            held = sum(1 for c in known if c[level])
            cells.append(f"{held} ({100.0 * held / len(known):.1f} %)")
        print(f"| {kind} | {name} | {len(known)} | {cells[0]} | {cells[1]} |")
total = lambda key: sum(c[key] for c in checks)
errors = [abs(w["relative_error"]) for w in wheels]
print(f"\nrates within 10 % or inside the interval: {total('rates_ok')} of {len(wheels)} "
      f"(largest error {100.0 * max(errors):.1f} %); reprofilings found: "
      f"{total('reprofilings_found')} of {total('reprofilings')}; drifting sensors flagged: "
      f"{total('drifting_flagged')} of {total('drifting')}; healthy sensors flagged: "
      f"{total('healthy_flagged')}; fleets passing: {sum(c['passed'] for c in checks)} of "
      f"{len(checks)}")
# How wide the 95 % intervals are: half the rate's in % of the rate, half the warning date's in days.
rate_widths, date_widths = [], []
for estimate in estimates:
    for w in estimate["wheels"]:
        rate = w["wear_rate_mm_per_1000km"]
        rate_widths.append(50.0 * (w["wear_rate_high"] - w["wear_rate_low"]) / rate)
        warning = w["warning"]
        if not warning["reached"] and warning["days_low"] is not None \
                and warning["days_high"] is not None:
            date_widths.append((warning["days_high"] - warning["days_low"]) / 2.0)
print(f"95 % intervals: rate +- {statistics.median(rate_widths):.2f} % (median; 90th percentile "
      f"{sorted(rate_widths)[int(0.9 * len(rate_widths))]:.2f} %), warning date +- "
      f"{statistics.median(date_widths):.1f} days (median of {len(date_widths)})")
PY
