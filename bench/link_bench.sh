#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Samples per second of the windowed board link (docs/board.md, "Windowed session"), for
# docs/board.md's table:
#   bash bench/link_bench.sh [BUILD_DIR]     (BUILD_DIR defaults to build; needs its link_bench)
#   sudo nice -n -5 bash bench/link_bench.sh build   (as the docs' figures were taken)
# The link runs in wall-clock time, so a run whose threads wait for a core behind other users'
# compilers reads low; the protocol-model runs use a few per cent of a core, and a higher priority
# (a negative niceness, RTL_NICENESS below puts the Verilated runs back to 0) keeps them honest
# on a shared machine without taking much from anyone.
# Runs build/bench/link_bench (12 interleaved channels through the host library and a simulated
# FTDI chip to the board's protocol model, every reply checked against the filter model) for each
# window 1..32, baud 115200..921600 and 3 Mbaud, latency timer 1 and 16 ms (the median of three one-second runs each), and
# prints a markdown table of samples/s per window (columns: baud / latency timer); then the
# Verilated 12-channel top in the protocol model's place, through the chip and without it (the
# simulator's own ceiling); last the line for 921600 baud and the default 16 ms timer.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="${1:-$here/../build}"
bench="$build/bench/link_bench"
if [ ! -x "$bench" ]; then
  echo "link_bench.sh: $bench not found (cmake --build $build --target link_bench)" >&2
  exit 2
fi
WINDOWS=(1 2 4 8 12 16 24 32)
BAUDS=(115200 230400 460800 921600 3000000)
LATENCIES=(16 1)
SECONDS_PER_RUN=1
RTL_NICENESS=$(( -$(nice) ))

# samples/s of one configuration: the median of three runs (the machine is shared: a run whose
# threads were starved of a core reads low); fails on a mismatch against the model.
rate() {
  local line runs=()
  local niceness=0
  # The Verilated top keeps a core busy: it runs at the niceness the script was started with.
  [[ " $* " == *" --rtl "* ]] && niceness=$RTL_NICENESS
  for _ in 1 2 3; do
    line="$(nice -n "$niceness" "$bench" --seconds "$SECONDS_PER_RUN" "$@")" || { echo "link_bench.sh: link_bench $* failed: $line" >&2; exit 1; }
    runs+=("$(echo "$line" | sed -E 's/.* ([0-9]+) samples\/s.*/\1/')")
  done
  printf '%s\n' "${runs[@]}" | sort -n | sed -n 2p
}

header="| window |"
rule="|---|"
for latency in "${LATENCIES[@]}"; do
  for baud in "${BAUDS[@]}"; do
    header+=" $baud / $latency ms |"
    rule+="---|"
  done
done
header+=" Verilated top, 921600 / 16 ms | Verilated top, no FTDI chip |"
rule+="---|---|"
echo "$header"
echo "$rule"
best_window=0
best_rate=0
for window in "${WINDOWS[@]}"; do
  row="| $window |"
  for latency in "${LATENCIES[@]}"; do
    for baud in "${BAUDS[@]}"; do
      r="$(rate --window "$window" --baud "$baud" --latency-ms "$latency")"
      row+=" $r |"
      if [ "$baud" = 921600 ] && [ "$latency" = 16 ] && [ "$r" -gt "$best_rate" ]; then
        best_rate="$r"
        best_window="$window"
      fi
    done
  done
  row+=" $(rate --window "$window" --baud 921600 --latency-ms 16 --rtl) |"
  row+=" $(rate --window "$window" --baud 921600 --latency-ms 16 --rtl --no-ftdi) |"
  echo "$row"
done
margin="$(awk -v n="$best_rate" 'BEGIN { printf "%.1f", n / 1200 }')"
echo "link: 921600 baud, latency timer 16 ms, window $best_window: $best_rate samples/s, $margin x 12 wheels at 100 Hz"
