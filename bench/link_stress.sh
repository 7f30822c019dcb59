#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The board link's recovery under stress (docs/board.md, "Recovery under stress"): the reset and
# loss tests of the windowed link through the simulated FTDI chip (tb/board/board_ftdi_stream_test)
# and the loss test of the plain link (tb/board/board_stream_test), each RUNS times, one process
# per test and run, while BUSY busy loops that the script starts (and stops on exit) load the
# machine beside whatever else runs on it. A stress run, not a test: CTest runs each test once.
#   bash bench/link_stress.sh [BUILD_DIR] [RUNS] [BUSY] [PICK] [SIDE_BY_SIDE]
#                                                     (defaults: build 200 2 . 1)
# PICK, a regular expression, keeps the tests whose names match it (BoardFtdiStream: the FTDI
# link's). SIDE_BY_SIDE runs that many runs at a time (each one test after another), which loads
# the machine further and shortens the wall-clock time: the tests mostly wait for the link's
# timeouts. Needs the BUILD_DIR test binaries of the tests it runs. Writes BUILD_DIR/link_stress/:
# runs.csv (run,test,outcome,seconds: one row per test and run), the log of every failed run
# (fail-<run>-<test>.log), summary.txt (per test and overall: runs, failures, min/median/max
# seconds; the load average at the start and at the end, and the 1-minute one every 30 s between:
# load.txt) and figures.md, the same as a Markdown table under the command that made it, with
# each failed run's error line (docs/board.md links a copy of it: docs/link_stress_figures.md).
# Exit status 0 when every run passed, 1 when one failed, 2 when the binaries are missing.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
build="$(realpath -m "${1:-$here/../build}")"
runs="${2:-200}"
busy="${3:-2}"
pick="${4:-.}"
side_by_side="${5:-1}"
out="$build/link_stress"

# The tests: binary, then gtest name. The FTDI link's reset, loss and late-reply tests (every one
# that recovers a session: a replay after a reset, with replies held past the timeout, with
# resets and lost bytes at SEQs 0xA5 and 0x5A, after a damaged request the board took; go-back-N
# after a loss; stray replies after an early timeout; the stop after too many resets) and the
# plain link's loss test.
tests=(
  "board_ftdi_stream_test BoardFtdiStream.BoardResetsDuringTheSessionAreRecoveredByAReplay"
  "board_ftdi_stream_test BoardFtdiStream.RepliesHeldPastTheTimeoutAroundResetsAreRecoveredExactly"
  "board_ftdi_stream_test BoardFtdiStream.ResetsAndLostBytesAtTheSyncLikeSeqsAreRecovered"
  "board_ftdi_stream_test BoardFtdiStream.ADamagedRequestTheBoardTakesForAnotherChannelIsRecovered"
  "board_ftdi_stream_test BoardFtdiStream.ADamagedRequestTheBoardFiltersOnAnotherChannelIsRecovered"
  "board_ftdi_stream_test BoardFtdiStream.LossCorruptionAndLostRepliesGiveEveryOutputOnce"
  "board_ftdi_stream_test BoardFtdiStream.RepliesLateForTheTimeoutAreStrayNotFilteredTwice"
  "board_ftdi_stream_test BoardFtdiStream.ABoardThatKeepsResettingStopsTheSession"
  "board_stream_test BoardStream.NoisyCableIsRecoveredBitExact"
)
picked=()
for t in "${tests[@]}"; do [[ ${t#* } =~ $pick ]] && picked+=("$t"); done
tests=("${picked[@]}")
if [[ ${#tests[@]} -eq 0 ]]; then
  echo "link_stress.sh: no test matches '$pick'" >&2
  exit 2
fi
for t in "${tests[@]}"; do
  if [[ ! -x $build/tb/${t%% *} ]]; then
    echo "link_stress.sh: $build/tb/${t%% *} not found (cmake --build $build --target ${t%% *})" >&2
    exit 2
  fi
done

# The load: busy loops of our own, stopped by their process ids however the script ends.
loops=()
stop_loops() { for pid in "${loops[@]}"; do kill "$pid" 2>/dev/null || true; done; }
trap stop_loops EXIT
for ((b = 0; b < busy; ++b)); do
  (while :; do :; done) &
  loops+=("$!")
done

mkdir -p "$out"
rm -f "$out"/fail-*.log "$out"/runs-*.csv "$out"/load.txt
csv="$out/runs.csv"
load_start=$(cut -d' ' -f1-3 /proc/loadavg)
# The 1-minute load average every 30 s while the runs go.
(while :; do cut -d' ' -f1 /proc/loadavg >>"$out/load.txt"; sleep 30; done) &
loops+=("$!")
command="bash bench/link_stress.sh $(basename "$build") $runs $busy '$pick' $side_by_side"

# Runs first, first + side_by_side, ... each test in its own process; one CSV per worker.
worker() {
  local first=$1 run t binary name start end outcome
  for ((run = first; run <= runs; run += side_by_side)); do
    for t in "${tests[@]}"; do
      binary=${t%% *}
      name=${t#* }
      start=$(date +%s.%N)
      if "tb/$binary" --gtest_filter="$name" >"$out/current-$first.log" 2>&1; then
        outcome=pass
      else
        outcome=fail
        cp "$out/current-$first.log" "$out/fail-$run-$name.log"
      fi
      end=$(date +%s.%N)
      printf '%d,%s,%s,%.3f\n' "$run" "$name" "$outcome" \
        "$(awk "BEGIN { print $end - $start }")" >>"$out/runs-$first.csv"
    done
    (( run % 20 == 0 )) && echo "link_stress.sh: run $run of $runs done"
  done
  rm -f "$out/current-$first.log"
}
# Working directory: the build folder, as under CTest.
cd "$build"
workers=()
for ((w = 1; w <= side_by_side; ++w)); do
  worker "$w" &
  workers+=("$!")
  loops+=("$!")  # stopped with the busy loops if the script is stopped
done
wait "${workers[@]}"
{ echo "run,test,outcome,seconds"; cat "$out"/runs-*.csv | sort -t, -k1,1n -s; } >"$csv"
rm -f "$out"/runs-*.csv
failed=0
grep -q ',fail,' "$csv" && failed=1
load_end=$(cut -d' ' -f1-3 /proc/loadavg)

# runs, failures, min/median/max seconds of the rows whose test matches $1 (a regex).
summarise() {
  awk -F, -v pick="$1" 'NR > 1 && $2 ~ pick { print $3, $4 }' "$csv" | sort -k2,2 -g |
    awk -v label="$2" '{ n++; if ($1 != "pass") f++; s[n] = $2 }
      END {
        if (n == 0) exit
        med = n % 2 ? s[(n + 1) / 2] : (s[n / 2] + s[n / 2 + 1]) / 2
        printf "%s: %d runs, %d failures, seconds min %.2f median %.2f max %.2f\n",
               label, n, f + 0, s[1], med, s[n] }'
}
load_during=$(sort -g "$out/load.txt" | awk '{ s[++n] = $1 } END {
  printf "min %s, median %s, max %s", s[1], s[int((n + 1) / 2)], s[n] }')
load_line="busy loops: $busy; runs side by side: $side_by_side; load average (1, 5, 15 min) at the start: $load_start, at the end: $load_end; 1-minute load average every 30 s during the run: $load_during"
{
  for t in "${tests[@]}"; do summarise "^${t#* }\$" "${t#* }"; done
  summarise "." "all tests ($runs runs of ${#tests[@]})"
  echo "$load_line"
} | tee "$out/summary.txt"

# The same as Markdown: the command, a row per test, the load, the failed runs' errors.
{
  echo "# The board link's recovery under stress: figures"
  echo
  echo "Written by \`bench/link_stress.sh\` (docs/board.md, \"Recovery under stress\"), on $(nproc) cores:"
  echo
  echo "    $command"
  echo
  echo "| test | runs | failures | seconds min | median | max |"
  echo "|---|---|---|---|---|---|"
  sed -E 's/^(.*): ([0-9]+) runs, ([0-9]+) failures, seconds min ([0-9.]+) median ([0-9.]+) max ([0-9.]+)$/| \1 | \2 | \3 | \4 | \5 | \6 |/' \
    "$out/summary.txt" | grep '^|'
  echo
  echo "${load_line^}."
  echo
  if [[ $failed -eq 0 ]]; then
    echo "Every run passed."
  else
    echo "Failed runs (run, test: the log's first error line; logs in \`link_stress/fail-*.log\`):"
    echo
    awk -F, 'NR > 1 && $3 == "fail" { print $1, $2 }' "$csv" | while read -r run name; do
      line=$(grep -m1 -E 'what\(\)|does not answer|Failure|error' "$out/fail-$run-$name.log" || true)
      echo "- run $run, $name: ${line:-no error line}"
    done
  fi
} >"$out/figures.md"
exit "$failed"
