#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The reliability build (docs/reliability.md): the project built with clang under AddressSanitizer
# and UndefinedBehaviorSanitizer, its fast unit tests run there, and each libFuzzer harness run for
# a short time on a copy of its kept corpus. CI runs the default (the Reliability.* CTest test).
#
#   bash scripts/reliability.sh [--build-dir DIR] [--fuzz-seconds N] [--all]
#
# --all builds and runs the whole test suite under the sanitizers instead of the fast part (about
# three hours on two shared cores: two to build, one to test). A fuzzer that finds a crash leaves
# the input in DIR/fuzz_findings/ and the script fails with the command that reproduces it; keep
# such an input in tests/fuzz/corpus/<harness>/ once it is fixed, so every build replays it.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="$root/build/reliability"
fuzz_seconds=10
all=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build="$2"; shift 2 ;;
    --fuzz-seconds) fuzz_seconds="$2"; shift 2 ;;
    --all) all=1; shift ;;
    *) echo "reliability.sh: unknown argument '$1' (valid: --build-dir DIR, --fuzz-seconds N, --all)" >&2; exit 2 ;;
  esac
done

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
export CCACHE_BASEDIR="$root"

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
