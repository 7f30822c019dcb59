#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Synthesises iir_core for Artix-7 (xc7) with Yosys for one coefficient set and prints the cells.
#   rtl/syn/synth_xc7.sh COEFF_DIR [--expect-dsp N] [--log FILE]
# COEFF_DIR holds iir_coeffs_pkg.sv and coeffs.mem (e.g. coeffs/vehicle_sos). With --expect-dsp
# the exit status is 1 unless the flattened netlist has exactly N DSP48E1 cells.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
rtl="$(cd "$here/.." && pwd)"
if [ $# -lt 1 ]; then
  echo "usage: $0 COEFF_DIR [--expect-dsp N] [--log FILE]" >&2
  exit 2
fi
set_dir="$(cd "$1" && pwd)"
shift
expect=""
log=""
while [ $# -gt 0 ]; do
  case "$1" in
    --expect-dsp) expect="$2"; shift 2 ;;
    --log) log="$2"; shift 2 ;;
    *) echo "synth_xc7: unknown argument $1" >&2; exit 2 ;;
  esac
done
for f in "$set_dir/iir_coeffs_pkg.sv" "$set_dir/coeffs.mem"; do
  [ -f "$f" ] || { echo "synth_xc7: $f is missing" >&2; exit 2; }
done

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
[ -n "$log" ] || log="$work/yosys.log"

# -defer: the ROM path is set before the core is elaborated (its default would be read first).
cat > "$work/synth.ys" <<YS
read_verilog -sv $set_dir/iir_coeffs_pkg.sv
read_verilog -sv -defer $rtl/iir_mac.sv $rtl/iir_core.sv
chparam -set RomFile "$set_dir/coeffs.mem" iir_core
synth_xilinx -family xc7 -top iir_core -flatten
tee -o $work/stat.txt stat -tech xilinx
YS

if ! yosys -q -l "$log" -s "$work/synth.ys" >/dev/null 2>&1; then
  echo "synth_xc7: yosys failed for $set_dir; see $log (run: yosys -s $work/synth.ys)" >&2
  grep -m 3 -i "error" "$log" >&2 || true
  exit 1
fi

count() { awk -v cell="$1" '$1 == cell { n = $2 } END { print n + 0 }' "$work/stat.txt"; }
luts=0
for l in LUT1 LUT2 LUT3 LUT4 LUT5 LUT6; do luts=$((luts + $(count $l))); done
dsp=$(count DSP48E1)
# Distributed RAM (the load registers): LUT6 sites per cell, which Yosys does not count as LCs.
lutram=$(( 4 * ($(count RAM32M) + $(count RAM64M)) + 2 * ($(count RAM32X1D) + $(count RAM64X1D)) + $(count RAM32X1S) + $(count RAM64X1S) ))
lcs=$(awk '/Estimated number of LCs/ { n = $NF } END { print n + 0 }' "$work/stat.txt")
echo "synth_xc7: $(basename "$set_dir"): DSP48E1 $dsp, LUT $luts, FDRE $(count FDRE), CARRY4 $(count CARRY4), MUXF7 $(count MUXF7), MUXF8 $(count MUXF8), estimated LCs $lcs, LUTRAM sites $lutram"

if [ -n "$expect" ] && [ "$dsp" -ne "$expect" ]; then
  echo "synth_xc7: expected $expect DSP48E1, got $dsp (reproduce: rtl/syn/synth_xc7.sh $set_dir --expect-dsp $expect)" >&2
  exit 1
fi
