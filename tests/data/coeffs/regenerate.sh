#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Regenerates the small SOS coefficient sets that the co-simulation tests build the RTL for
# (orders 1, 2, 3, 4, 8 and 12; fs = 6 Hz, fc = 0.5 Hz, like the measurement filter), the
# first-order direct form df1_order1 (the one set `flange design` makes with sections of order
# M = 1), df1_order1x2 (test-only: df1_order1's section twice, cascade_set.py, so that K = 2 with
# M = 1 reaches the core's stall path), and the multichannel cores: the vehicle filter shared by 4 and by 12 channels (loco_ch4, loco_ch12), and
# three channels with a coefficient set each (loco_sets3).
#   bash tests/data/coeffs/regenerate.sh [FLANGE]          rewrite every set folder here
#   bash tests/data/coeffs/regenerate.sh --check [FLANGE]  regenerate into a temp folder, compare
# FLANGE defaults to build/flange.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
check=0
if [ "${1:-}" = "--check" ]; then
  check=1
  shift
fi
flange="${1:-$here/../../../build/flange}"
# set name | arguments of `flange design`
SETS=()
for order in 1 2 3 4 8 12; do
  SETS+=("sos_order$order|--fs 6 --order $order --fc 0.5 --structure sos --name sos_order$order")
done
# M = 1: a direct form of order 1 (K = 1). An sos design stores a first-order section as a biquad
# (M = 2), so this is the only M = 1 set `flange design` can make.
SETS+=("df1_order1|--fs 6 --order 1 --fc 0.5 --structure df1 --name df1_order1")
for channels in 4 12; do
  SETS+=("loco_ch$channels|--fs 100 --order 7 --fc 0.259 --structure sos --channels $channels --name loco_ch$channels")
done
# A set per channel: the vehicle filter and two wider ones, in one shared format.
SETS+=("loco_sets3|--fs 100 --order 7 --channel-fc 0.259,0.5,1.0 --structure sos --name loco_sets3")

out_root="$here"
if [ "$check" -eq 1 ]; then
  out_root="$(mktemp -d)"
  trap 'rm -rf "$out_root"' EXIT
fi

# Every file of a set folder here against the fresh one.
status=0
compare() {
  local name="$1" how="$2"
  for file in "$here/$name"/* "$out_root/$name"/*; do
    base="$(basename "$file")"
    if ! cmp -s "$here/$name/$base" "$out_root/$name/$base"; then
      echo "regenerate: $name/$base differs from a fresh run of: $how" >&2
      echo "  to update: bash tests/data/coeffs/regenerate.sh" >&2
      status=1
    fi
  done
}

for entry in "${SETS[@]}"; do
  name="${entry%%|*}"
  read -r -a args <<<"${entry#*|} --no-plot"

  "$flange" design "${args[@]}" --out "$out_root/$name" >/dev/null
  if [ "$check" -eq 1 ]; then compare "$name" "flange design ${args[*]}"; fi
done
python3 "$here/cascade_set.py" "$out_root/df1_order1" 2 "$out_root/df1_order1x2" df1_order1x2
if [ "$check" -eq 1 ]; then compare df1_order1x2 "python3 tests/data/coeffs/cascade_set.py df1_order1 2"; fi
exit "$status"
