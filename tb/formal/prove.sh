#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Proves one formal property of the RTL with Yosys's SAT solver (docs/formal.md).
#   tb/formal/prove.sh PROPERTY [COEFF_DIR] [--bmc N] [--param NAME=VALUE] [--keep DIR]
# PROPERTY is a test name's last part, e.g. LatencyExact (core properties take the coefficient
# set folder, e.g. coeffs/vehicle_sos) or ValidOnlyWithMatchingCrc (the board's frame decoder).
# --bmc N replaces the property's proof by a bounded check of N cycles from reset; --keep DIR
# keeps the Yosys script, log and any counterexample (VCD) there; --param sets a parameter of the
# wrapper (e.g. ClksPerBit=4 for the frame decoder, to reach a whole frame in a short bounded
# check). Exit status 0: proven.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"
rtl="$root/rtl"

usage() {
  echo "usage: $0 PROPERTY [COEFF_DIR] [--bmc N] [--param NAME=VALUE] [--keep DIR]" >&2
  exit 2
}
[ $# -ge 1 ] || usage
property="$1"
shift
set_dir=""
bmc=""
keep=""
params=""
while [ $# -gt 0 ]; do
  case "$1" in
    --bmc) [ $# -ge 2 ] || usage; bmc="$2"; shift 2 ;;
    --keep) [ $# -ge 2 ] || usage; keep="$2"; shift 2 ;;
    --param) [ $# -ge 2 ] || usage; params="$params $2"; shift 2 ;;
    -*) usage ;;
    *) [ -z "$set_dir" ] || usage; set_dir="$(cd "$1" && pwd)"; shift ;;
  esac
done

# Per property: the wrapper, the assertion labels it proves (Yosys selection patterns) and the
# proof: "induct N" is k-induction up to length N (sat -tempinduct: the base case from reset and
# the induction step from any state), "bmc N" a bounded check of N cycles after reset. A proof
# that holds closes at a short length (1 with the schedule invariants); N only bounds the search
# for a counterexample from reset when it does not. The latency and busy/overrun properties are
# stated on the ports; with the schedule invariants (sched_*, proven with them) they close at
# length 1, and their ...FromPorts twins prove the same assertions without any helper, by
# k-induction up to L + 16 cycles (the slow, independent proof; FLANGE_FORMAL_FULL).
case "$property" in
  LatencyExact)             unit=core; labels="latency_* sched_*";    proof="induct 100" ;;
  LatencyExactFromPorts)    unit=core; labels="latency_*";            proof="induct 100" ;;
  BusyOverrunAsDocumented)
                            unit=core; labels="busy_* overrun_* history_* sched_*"; proof="induct 100" ;;
  BusyOverrunAsDocumentedFromPorts)
                            unit=core; labels="busy_* overrun_* history_*"; proof="induct 100" ;;
  ScheduleAsDocumented)     unit=core; labels="sched_*";              proof="induct 40" ;;
  BtcWithinRom)             unit=core; labels="btc_* sched_*";        proof="induct 40" ;;
  LoadRegistersWithinLines) unit=core; labels="lr_* sched_*";         proof="induct 40" ;;
  AccumulatorNeverWraps)    unit=core; labels="acc_* sched_*";        proof="induct 12" ;;
  AccumulatorWithinGeneratorBound)
                            unit=core; labels="gen_* acc_* sched_*";  proof="induct 8" ;;
  ChannelsIndependent)      unit=core; labels="channel_* sched_* lr_*"; proof="induct 40" ;;
  ValidOnlyWithMatchingCrc) unit=decoder; labels="crc_* rx_*";        proof="induct 12" ;;
  *) echo "prove: unknown property $property" >&2; usage ;;
esac
if [ -n "$bmc" ]; then
  proof="bmc $bmc"
fi

work="$(mktemp -d)"
cleanup() { rm -rf "$work"; }
trap cleanup EXIT
script="$work/prove.ys"
log="$work/yosys.log"

case "$unit" in
  core)
    [ -n "$set_dir" ] || { echo "prove: $property needs a coefficient set folder" >&2; usage; }
    for f in "$set_dir/iir_coeffs_pkg.sv" "$set_dir/coeffs.mem"; do
      [ -f "$f" ] || { echo "prove: $f is missing" >&2; exit 2; }
    done
    wrapper="$here/iir_core_props.sv"
    top=iir_core_props
    # -defer: the ROM path is set before the core is elaborated (as in rtl/syn/synth_xc7.sh).
    # The RTL is read as for synthesis (its simulation-only checks stay out); the wrapper with
    # -formal.
    read_sources="read_verilog -sv $set_dir/iir_coeffs_pkg.sv
read_verilog -sv -defer $rtl/iir_mac.sv $rtl/iir_core.sv
read_verilog -formal -sv -defer $wrapper
chparam -set RomFile \"$set_dir/coeffs.mem\" $top"
    what="$property for $(basename "$set_dir")"
    ;;
  decoder)
    wrapper="$here/frame_decoder_props.sv"
    top=frame_decoder_props
    read_sources="read_verilog -sv $rtl/board/crc8.sv $rtl/board/uart_rx.sv $rtl/board/frame_decoder.sv
read_verilog -formal -sv -defer $wrapper"
    what="$property"
    ;;
esac

# The wrapper's probes: each `assign probe = inst.signal;` line of its `ifndef YOSYS block (read by
# Verilator as written) becomes a connection made after flattening, where Yosys names the signal
# inst.signal. -nounset: the probe may already be an alias of a wire that proc made for it.
probes="$(sed -n '/^`ifndef YOSYS/,/^`endif/ s/^ *assign \([A-Za-z0-9_]*\) *= *\([A-Za-z0-9_]*\.[A-Za-z0-9_.]*\);.*/connect -nounset -set \1 \2/p' "$wrapper")"
[ -n "$probes" ] || { echo "prove: no probes found in $wrapper" >&2; exit 2; }

keep_sel=""
for l in $labels; do keep_sel="$keep_sel n:$l"; done
nlabels=$(echo $labels | wc -w)
union=""
for ((i = 1; i < nlabels; i++)); do union="$union %u"; done

# ABC first rewrites the logic into AND and XOR gates (function preserving) for two proofs that
# are slow on RTL cells: the decoder's CRC against the CRC by polynomial division, a parity
# problem (20 s on RTL cells, under 1 s on gates), and the generator's bound, which needs the
# multiplier's products of ROM words (165 s on RTL cells for measurement_sos, 21 s on gates).
gates=""
if [ "$unit" = decoder ] || [ "$property" = AccumulatorWithinGeneratorBound ]; then
  gates="techmap
opt -fast
abc -g XOR,AND
opt_clean"
fi

read -r kind depth <<<"$proof"
if [ "$kind" = induct ]; then
  sat_args="-tempinduct -maxsteps $depth"
else
  sat_args="-tempinduct-baseonly -maxsteps $depth"
fi

chparams=""
for p in $params; do
  chparams="$chparams
chparam -set ${p%%=*} ${p#*=} $top"
  what="$what ($p)"
done

cat >"$script" <<YS
$read_sources$chparams
hierarchy -check -top $top
proc
flatten
$probes
# Only this property's assertions remain.
select -assert-min 1 t:\$assert$keep_sel$union %i
delete t:\$assert$keep_sel$union %d
memory -nomap
memory_map
opt -fast
opt_clean
dffunmap
$gates
# Cycle 1 is the reset cycle; the assertions hold from cycle 2 on.
sat $sat_args -prove-asserts -set-assumes -seq 1 -set-at 1 rst_ni 0 -show-inputs -show-regs -dump_vcd $work/counterexample.vcd -verify
YS

status=0
TIMEFORMAT='%U %S %R'
{ time yosys -q -l "$log" -s "$script" >/dev/null 2>&1 || status=$?; } 2>"$work/time"
read -r user sys elapsed <"$work/time"
cpu=$(awk -v u="$user" -v s="$sys" 'BEGIN { printf "%.1f", u + s }')
elapsed=$(awk -v r="$elapsed" 'BEGIN { printf "%.1f", r }')
steps=$( (grep -o "induction with length [0-9]*" "$log" || true) | tail -1 | awk "{ print \$4 }")

if [ -n "$keep" ]; then
  mkdir -p "$keep"
  cp "$work"/* "$keep"/
  sed -i "s|$work|$keep|g" "$keep/prove.ys"
fi

repro="tb/formal/prove.sh $property${set_dir:+ ${set_dir#$root/}}${bmc:+ --bmc $bmc}"
for p in $params; do repro="$repro --param $p"; done
repro="$repro --keep logs/formal/$property"
if [ "$status" -ne 0 ]; then
  echo "prove: FAILED: $what ($kind, length ${steps:-?}, $cpu s CPU)" >&2
  if grep -q "model found for base case" "$log"; then
    echo "prove: a counterexample from reset: the property is violated" >&2
  elif grep -q "Reached maximum number of time steps -> proof failed" "$log"; then
    echo "prove: no counterexample from reset within the length, but no induction either: the" \
         "counterexample below starts from an unreachable state or the length is too short" >&2
  else
    grep -m 1 -E "ERROR" "$log" >&2 || true
  fi
  # Name the failing assertions: rerun with every signal shown and the assertion cells listed
  # (label, checked signal, enable), and read their values in the last step of the last model.
  diag="$work/diagnose.log"
  sed 's/^sat .* -show-inputs -show-regs /tee -q -o ASSERTS dump t:$assert\n&/; s/ -show-inputs -show-regs / -show-all /' \
    "$script" | sed "s|ASSERTS|$work/asserts.txt|" >"$work/diagnose.ys"
  yosys -q -l "$diag" -s "$work/diagnose.ys" >/dev/null 2>&1 || true
  awk '
    FNR == NR {
      if ($1 == "cell") { cell = $3; sub(/^\\/, "", cell) }
      if ($1 == "connect" && $2 == "\\A") a[cell] = $3
      if ($1 == "connect" && $2 == "\\EN") en[cell] = $3
      next
    }
    /Time Signal/ { delete value; last = 0 }
    $1 ~ /^[0-9]+$/ {
      if ($1 + 0 > last) { last = $1 + 0; delete value }
      if ($1 + 0 == last) value[$2] = $3
    }
    END {
      for (cell in a) {
        check = (a[cell] == "1'"'"'1") ? 1 : value[a[cell]]
        enable = (en[cell] == "1'"'"'1") ? 1 : value[en[cell]]
        if (check == "0" && enable == "1")
          printf "prove: assertion %s fails in cycle %d of the counterexample\n", cell, last
      }
    }' "$work/asserts.txt" "$diag" >&2 || true
  [ -z "$keep" ] || cp "$work"/diagnose.* "$work/asserts.txt" "$keep"/ 2>/dev/null || true
  echo "prove: reproduce (script, log and counterexample.vcd kept in logs/formal/$property):" >&2
  echo "  $repro" >&2
  exit 1
fi
if [ "$kind" = induct ]; then
  echo "prove: proven: $what (induction, length $steps, $cpu s CPU, $elapsed s)"
else
  echo "prove: bounded: $what holds for $depth cycles after reset ($cpu s CPU, $elapsed s)"
fi
