#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The reliability build (docs/reliability.md): the project built with clang under AddressSanitizer
# and UndefinedBehaviorSanitizer, its fast unit tests run there, and each libFuzzer harness run for
# a short time on a copy of its kept corpus. CI runs the default (the Reliability.* CTest test).
#
#   bash scripts/reliability.sh [--build-dir DIR] [--fuzz-seconds N] [--all | --tsan]
#
# --all builds and runs the whole test suite under the sanitizers instead of the fast part (about
# three hours on two shared cores: two to build, one to test). A fuzzer that finds a crash leaves
# the input in DIR/fuzz_findings/ and the script fails with the command that reproduces it; keep
# such an input in tests/fuzz/corpus/<harness>/ once it is fixed, so every build replays it.
#
# --tsan builds the tree with clang under ThreadSanitizer instead (build/tsan/; TSan cannot share a
# process with ASan) and runs a test of every thread the project starts (the list below, each with
# the threads it exercises); any report fails it. Nothing is suppressed.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build=""
fuzz_seconds=10
all=0
tsan=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift 2 ;;
    --fuzz-seconds) fuzz_seconds="$2"; shift 2 ;;
    --all) all=1; shift ;;
    --tsan) tsan=1; shift ;;
    *) echo "reliability.sh: unknown argument '$1' (valid: --build-dir DIR, --fuzz-seconds N, --all, --tsan)" >&2; exit 2 ;;
  esac
done
if [ "$all" -eq 1 ] && [ "$tsan" -eq 1 ]; then
  echo "reliability.sh: --all and --tsan are two builds; run them one at a time" >&2
  exit 2
fi
export CCACHE_BASEDIR="$root"

# The tests that start a thread of the project, as "binary gtest-filter reason" (a test that
# starts no thread cannot race, and costs a TSan build its time). The sites were found with
#   grep -rn "std::thread\|std::async\|jthread\|pthread\|pragma omp" --include=*.cpp --include=*.h
# and each is reached by a test below (docs/reliability.md says which; checked with a breakpoint on
# pthread_create and each thread's call stack). Kept small enough to finish in minutes: a test
# that reaches only sites another one reaches is not here (the ten-case self-test, the improved
# twin's re-diagnoses on two threads).
# Not here: host/store (no thread: SQLite and PostgreSQL are used from the caller's thread; its
# tests fork, which TSan allows), tb/systemc (SystemC's processes are coroutines on one thread,
# whose stack switching TSan does not follow), the fleet simulation (runs its chains on one thread).
tsan_tests=(
  "recording_batch_reader_test * host/recording: the read-ahead thread and the caller, strict and lenient, errors in a later batch"
  "run_output_csv_test * host/run: the writer thread behind the caller, a failed write reported across it"
  "run_command_test RunCommand.WithTwoThreadsTheFirstBadLineIsReportedAndTheOutputIsTheSame flange run: the reader and writer threads around the filter, stopped by bad lines"
  "board_ftdi_stream_test -BoardFtdiStream.WindowCarriesFourTimesTwelveWheelsAt100Hz* host/board_link sessions against the board thread (tb/board/pty_board.h) through the FTDI model: windows, losses, resets (not the two tests of the protocol model's throughput, a speed the instrumented build does not keep on a loaded machine; RepliesLateForTheTimeoutAreStrayNotFilteredTwice runs that model on the board thread)"
  "board_stream_test * flange stream through a pseudo-terminal to the board thread"
  "board_channels_stream_test * the multichannel stream through a pseudo-terminal to the board thread"
  "diagnose_test DiagnoseCommand.WritesJsonAndReportWithVerdictFirst:Diagnose.NullRecordingGivesNone flange diagnose's std::async work: replays, null replicas, library candidates, free shapes, inclusion shares"
  "diagnose_selftest_test DiagnoseSelftest.CasesOnTwoThreadsGiveWhatEachGivesAlone:DiagnoseSelftest.AShortPairIsNamedWithAPickGivenAFreeShape the self-test's cases on two threads (run_in_parallel), each a whole diagnosis; a pair through both passes at once, a free shape and the final fit's inclusion shares"
  "alt_selftest_test AltSelftestCommand.RunsBlindAndPrintsItsSeedAndTheTableByClass the alternative reality's self-test, two pairs rendered and diagnosed on two threads (run_in_parallel)"
)

# Builds the tree under ThreadSanitizer and runs tsan_tests; fails on the first report.
run_tsan() {
  [ -n "$build" ] || build="$root/build/tsan"
  mkdir -p "$(dirname "$build")"
  cmake -S "$root" -B "$build" -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFLANGE_SANITIZE=thread -DFLANGE_WERROR=ON \
    > "$build.configure.log" 2>&1 || { cat "$build.configure.log" >&2; exit 1; }
  local entry binary filter targets=()
  for entry in "${tsan_tests[@]}"; do targets+=("${entry%% *}"); done
  cmake --build "$build" --target "${targets[@]}"

  # halt_on_error: the first report fails the test; second_deadlock_stack: both stacks of a
  # lock-order inversion.
  export TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1:history_size=4"
  echo "== tests that start threads, under TSan"
  local started=$SECONDS
  for entry in "${tsan_tests[@]}"; do
    read -r binary filter _ <<< "$entry"
    local path log="$build/$binary.tsan.log" t0=$SECONDS
    path="$(find "$build/tests" "$build/tb" -name "$binary" -type f -perm -u+x | head -1)"
    if ! (cd "$build" && "$path" --gtest_brief=1 --gtest_filter="$filter") > "$log" 2>&1 \
       || grep -q "WARNING: ThreadSanitizer" "$log"; then
      grep -A40 "WARNING: ThreadSanitizer" "$log" >&2 || tail -40 "$log" >&2
      echo "reliability: $binary failed under TSan (reproduce: cd $build && TSAN_OPTIONS='$TSAN_OPTIONS' $path --gtest_filter='$filter')" >&2
      exit 1
    fi
    echo "  $binary: $(grep -E '^\[  PASSED  \]' "$log" | head -1) ($((SECONDS - t0)) s)"
  done
  echo "reliability: ThreadSanitizer clean, ${#tsan_tests[@]} programs in $((SECONDS - started)) s"
}
if [ "$tsan" -eq 1 ]; then
  run_tsan
  exit 0
fi
[ -n "$build" ] || build="$root/build/reliability"

harnesses=(recording_csv_fuzz filter_json_fuzz calibration_json_fuzz twin_json_fuzz
           effect_argument_fuzz frame_decoder_fuzz locomotive_manifest_fuzz)
# The unit tests that need no Verilated model: the project's own arithmetic, parsers and stages.
unit_tests=(butterworth_reference_test quantize_test thesis_filters_test filter_json_test
            iir_core_test reference_filter_test staged_fixed_point_test iir_core_fidelity_test
            polynomial_sensor_model_test effect_settings_test effect_signatures_test
            sensor_twin_test twin_file_test bench_scenario_test loco_scenario_test
            recording_csv_test regression_test thresholds_test yosys_synthesis_test
            locomotive_test locomotive_manifest_test)

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DFLANGE_SANITIZE=address,undefined -DFLANGE_FUZZ=ON \
  -DFLANGE_WERROR=ON > "$build.configure.log" 2>&1 \
  || { cat "$build.configure.log" >&2; exit 1; }

if [ "$all" -eq 1 ]; then
  cmake --build "$build"
  ctest --test-dir "$build" --output-on-failure -j2
  exit 0
fi

targets=("${unit_tests[@]}")
for h in "${harnesses[@]}"; do targets+=("${h}_libfuzzer" "${h}_replay"); done
cmake --build "$build" --target "${targets[@]}"

echo "== unit tests under ASan+UBSan"
for t in "${unit_tests[@]}"; do
  binary="$(find "$build/tests" -name "$t" -type f -perm -u+x | head -1)"
  (cd "$build" && "$binary" --gtest_brief=1) > "$build/$t.log" 2>&1 \
    || { tail -40 "$build/$t.log" >&2; echo "reliability: $t failed under the sanitizers (reproduce: $binary)" >&2; exit 1; }
  echo "  $t: $(grep -E '^\[  PASSED  \]' "$build/$t.log" | head -1)"
done

echo "== fuzzing, ${fuzz_seconds} s per harness"
findings="$build/fuzz_findings"
mkdir -p "$findings"
for h in "${harnesses[@]}"; do
  corpus="$build/fuzz_corpus/$h"
  mkdir -p "$corpus"
  cp -n "$root/tests/fuzz/corpus/$h/"* "$corpus/"
  log="$build/$h.fuzz.log"
  if ! "$build/tests/fuzz/${h}_libfuzzer" -max_total_time="$fuzz_seconds" -timeout=10 \
       -rss_limit_mb=2048 -artifact_prefix="$findings/$h-" "$corpus" > "$log" 2>&1; then
    tail -40 "$log" >&2
    echo "reliability: $h found a failing input in $findings (reproduce: $build/tests/fuzz/${h}_libfuzzer $findings/$h-*)" >&2
    exit 1
  fi
  echo "  $h: $(grep -E '^#[0-9]+.*(DONE|pulse)' "$log" | tail -1 | awk '{print $1, "runs,", $3, $4, "coverage"}')"
done
echo "reliability: sanitizers and fuzzing clean"
