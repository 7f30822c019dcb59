#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Yosys resources of iir_core against its channel count, for docs/synthesis.md#channels:
#   bash bench/synth_channels.sh [FLANGE]     (FLANGE defaults to build/flange)
# Runs `flange synth` on the vehicle filter for 1, 4 and 12 channels sharing one set and for 3
# channels with a set each, and prints the core's column of each report as one table.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$here/.."
flange="${1:-$root/build/flange}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

SETS=(coeffs/vehicle_sos tests/data/coeffs/loco_ch4 tests/data/coeffs/loco_ch12
      tests/data/coeffs/loco_sets3)
ROWS=("LUT6 sites (logic + distributed RAM)" "of which logic (Yosys estimated LCs)"
      "of which distributed RAM (load registers)" "FF (FDRE/FDSE/FDCE/FDPE)" "CARRY4" "DSP48E1"
      "BRAM36" "logic depth (\`ltp\`, cells)")

# The core's figure in one row of a `flange synth` report.
core_figure() {
  awk -F'|' -v row="$2" '{ r = $2; gsub(/^ +| +$/, "", r); v = $3; gsub(/^ +| +$/, "", v) }
                         r == row { print v; exit }' "$1"
}

header="| resource |"
rule="|---|"
for set in "${SETS[@]}"; do
  name="$(basename "$set")"
  channels="$(awk '/NumChannels =/ { gsub(";", "", $5); print $5 }' "$root/$set/iir_coeffs_pkg.sv")"
  sets="$(awk '/CoefSets =/ { gsub(";", "", $5); print $5 }' "$root/$set/iir_coeffs_pkg.sv")"
  "$flange" synth --coeffs "$root/$set" --out "$work/$name.md" --max-core-lut-percent 100 \
    --min-slack-percent 0 >/dev/null
  header+=" \`$name\` ($channels ch, $sets set$([ "$sets" = 1 ] || echo s)) |"
  rule+="---|"
done
echo "$header"
echo "$rule"
for row in "${ROWS[@]}"; do
  line="| $row |"
  for set in "${SETS[@]}"; do
    line+=" $(core_figure "$work/$(basename "$set").md" "$row") |"
  done
  echo "$line"
done
